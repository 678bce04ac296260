package robotworld.explorer.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robotworld.cluster.ClusterMember;
import robotworld.cluster.ClusterOptions;
import robotworld.core.RuntimeSettings;
import robotworld.core.TokenFile;
import robotworld.space.server.SpaceServer;

/**
 * {@code rwe space}: runs a standalone space server until Ctrl-C (or until its thread is interrupted), then stops
 * it cleanly. With {@code --cluster} the process is also a member of a clustered space (docs/cluster.md) and serves
 * that space; without it, nothing of the cluster is loaded.
 */
@Command(name = "space", mixinStandardHelpOptions = true,
        description = {"Run a space server: participants connect to the URL it prints.",
                "Listens on loopback unless --bind says otherwise. Runs until Ctrl-C.",
                "With --cluster it is also a member of a clustered space, with the members of --member."})
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

    @Option(names = "--max-connections-per-client", paramLabel = "N",
            defaultValue = "" + SpaceServer.Options.DEFAULT_PER_CLIENT,
            description = "most open connections from one address; a client with the token is not limited"
                    + " (default: ${DEFAULT-VALUE})")
    private int maxConnectionsPerClient;

    @Option(names = "--max-waiting-per-client", paramLabel = "N",
            defaultValue = "" + SpaceServer.Options.DEFAULT_PER_CLIENT,
            description = "most operations waiting at once from one address; a client with the token is not"
                    + " limited (default: ${DEFAULT-VALUE})")
    private int maxWaitingPerClient;

    @Option(names = "--request-read-ms", paramLabel = "MS",
            defaultValue = "" + SpaceServer.Options.DEFAULT_REQUEST_READ_MILLIS,
            description = "how long a request may take to arrive, from its first byte, before its connection is"
                    + " closed (default: ${DEFAULT-VALUE})")
    private long requestReadMillis;

    @Option(names = "--cluster", paramLabel = "NAME",
            description = "be a member of the clustered space of cluster NAME (letters, digits, . _ -)")
    private String cluster;

    @Option(names = "--member", paramLabel = "HOST:PORT", split = ",",
            description = "a member of the cluster to join through (repeat, or separate with commas; list every"
                    + " member, this one included; none: start alone and let the others list this one)")
    private List<String> members = new ArrayList<>();

    @Option(names = "--min-members", paramLabel = "N", defaultValue = "0",
            description = "fewest members that must see each other for the space to serve (default: a majority"
                    + " of the --member list)")
    private int minMembers;

    @Option(names = "--member-port", paramLabel = "P", defaultValue = "" + ClusterOptions.DEFAULT_PORT,
            description = "the port of this member's cluster traffic (default: ${DEFAULT-VALUE}; 0 picks a free one)")
    private int memberPort;

    @Option(names = "--member-bind", paramLabel = "ADDR",
            description = "the address this member listens on and announces to the others (default: --bind, which"
                    + " must then be one address, not 0.0.0.0)")
    private String memberBind;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        SpaceServer.Options options;
        try {
            options = SpaceServer.Options.defaults().port(port).bindAddress(bind)
                    .maxConnectionsPerClient(maxConnectionsPerClient).maxWaitingPerClient(maxWaitingPerClient)
                    .requestReadMillis(requestReadMillis);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage()
                    + " (--max-connections-per-client and --max-waiting-per-client at least 1,"
                    + " --request-read-ms at least 10)");
        }
        String token = tokenFile != null ? TokenFile.read(tokenFile) : RuntimeSettings.fromSystem().spaceToken();
        if (token != null) {
            options = options.token(token);
        }
        ClusterMember member = cluster == null ? null : startMember(out);
        SpaceServer server;
        try {
            server = member == null ? SpaceServer.start(options)
                    : SpaceServer.start(member.openSpace(ClusterMember.DEFAULT_SPACE), options);
        } catch (RuntimeException e) {
            if (member != null) {
                member.close();
            }
            throw e;
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            stop(server, member, out); // the JVM ends right after its hooks: report from here
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
            stop(server, member, out);
        }
        return 0;
    }

    private ClusterMember startMember(PrintWriter out) {
        String address = memberBind != null ? memberBind : bind;
        if (address.equals("0.0.0.0") || address.equals("::") || address.equals("[::]")) {
            throw new ParameterException(spec.commandLine(), "--cluster: a member announces one address to the"
                    + " others: give it with --member-bind ADDR (this computer's address on the members' network)");
        }
        ClusterOptions options;
        try {
            for (String each : members) {
                checkMember(each);
            }
            options = ClusterOptions.named(cluster).withMembers(members).withBindAddress(address)
                    .withPort(memberPort).withMinimumMembers(minMembers);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "--cluster: " + e.getMessage());
        }
        ClusterMember member = ClusterMember.start(options);
        out.println("cluster member of '" + cluster + "' at " + member.address() + ", seeing "
                + member.memberCount() + " member(s); the space serves while at least "
                + options.effectiveMinimumMembers() + " see each other");
        if (!"127.0.0.1".equals(address) && !"localhost".equals(address) && !"::1".equals(address)) {
            out.println("warning: cluster traffic is neither authenticated nor encrypted: keep port "
                    + memberPort + " reachable from the other members only");
        }
        out.flush();
        return member;
    }

    private static void checkMember(String member) {
        int colon = member.lastIndexOf(':');
        String host = colon < 0 ? member : member.substring(0, colon);
        if (host.isBlank() || !host.matches("[A-Za-z0-9.\\-]+|\\[[0-9A-Fa-f:.]+\\]")) {
            throw new IllegalArgumentException("a member is HOST:PORT (e.g. 10.0.0.2:5701), not '" + member + "'");
        }
        if (colon >= 0) {
            String portText = member.substring(colon + 1);
            if (!portText.matches("[0-9]{1,5}") || Integer.parseInt(portText) > 65_535) {
                throw new IllegalArgumentException("a member's port is a number up to 65535 (e.g. 10.0.0.2:5701), not '"
                        + member + "'");
            }
        }
    }

    private static void stop(SpaceServer server, ClusterMember member, PrintWriter out) {
        server.stop();
        if (member != null) {
            member.close(); // leaves gracefully: its share of the space moves to the others first
        }
        out.println("space server stopped");
        out.flush();
    }
}
