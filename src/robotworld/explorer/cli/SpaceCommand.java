package robotworld.explorer.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import robotworld.core.RuntimeSettings;
import robotworld.core.TokenFile;
import robotworld.space.server.SpaceServer;

/**
 * {@code rwe space}: runs a standalone space server until Ctrl-C (or until its thread is interrupted), then stops
 * it cleanly.
 */
@Command(name = "space", mixinStandardHelpOptions = true,
        description = {"Run a space server: participants connect to the URL it prints.",
                "Listens on loopback unless --bind says otherwise. Runs until Ctrl-C."})
final class SpaceCommand implements Callable<Integer> {

    @Option(names = "--port", paramLabel = "P", defaultValue = "" + SpaceServer.Options.DEFAULT_PORT,
            description = "TCP port (default: ${DEFAULT-VALUE}; 0 picks a free one)")
    private int port;

    @Option(names = "--bind", paramLabel = "ADDR", defaultValue = "127.0.0.1",
            description = "address to listen on (default: ${DEFAULT-VALUE}; 0.0.0.0 for every interface)")
    private String bind;

    @Option(names = "--token-file", paramLabel = "F",
            description = "file holding a secret token; clients must then send it as a bearer token"
                    + " (default: the token of RWE_SPACE_TOKEN or RWE_SPACE_TOKEN_FILE, if set)")
    private Path tokenFile;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        SpaceServer.Options options = SpaceServer.Options.defaults().port(port).bindAddress(bind);
        String token = tokenFile != null ? TokenFile.read(tokenFile) : RuntimeSettings.fromSystem().spaceToken();
        if (token != null) {
            options = options.token(token);
        }
        SpaceServer server = SpaceServer.start(options);
        CountDownLatch stopped = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            stop(server, out); // the JVM ends right after its hooks: report from here
            stopped.countDown();
        }, "rwe-space-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        out.println("space server listening on " + server.uri() + (token != null ? " (token required)" : ""));
        if (!"127.0.0.1".equals(bind) && !"localhost".equals(bind) && !"::1".equals(bind)) {
            out.println("warning: reachable from other hosts" + (token == null ? " without a token" : ""));
        }
        out.println("press Ctrl-C to stop");
        out.flush();
        try {
            stopped.await();
        } catch (InterruptedException e) {
            // stopped from inside the JVM (tests, embedding): stop as Ctrl-C would
            Runtime.getRuntime().removeShutdownHook(hook);
            stop(server, out);
        }
        return 0;
    }

    private static void stop(SpaceServer server, PrintWriter out) {
        server.stop();
        out.println("space server stopped");
        out.flush();
    }
}
