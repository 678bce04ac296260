package robotworld.space.server;

/** Starts and stops a space server, as a program embedding one does; run by {@link EmbeddedServerLoggingTest}. */
public final class EmbeddedServerMain {

    private EmbeddedServerMain() {
    }

    public static void main(String[] args) {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0))) {
            System.out.println("serving " + server.uri());
        }
    }
}
