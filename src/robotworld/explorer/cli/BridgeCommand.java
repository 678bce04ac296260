package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.net.BindException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import robotworld.bridge.FoxgloveBridge;
import robotworld.core.RuntimeSettings;
import robotworld.core.TokenFile;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldLayouts;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldTap;
import robotworld.space.Capi;
import robotworld.space.SpaceException;
import robotworld.telemetry.SafetyTelemetry;

/**
 * {@code rwe bridge WORLD [--port P]}: a Foxglove WebSocket endpoint showing a running world live, until Ctrl-C.
 */
@Command(name = "bridge", mixinStandardHelpOptions = true,
        description = {"Show a running RobotWorld in Foxglove or Lichtblick (see docs/foxglove.md): serves the",
                "Foxglove WebSocket protocol (foxglove.websocket.v1) with one channel per module, liveness, stops",
                "and the simulated robots' ground truth. Listens on loopback unless --bind says otherwise.",
                "Runs until Ctrl-C or --for SECONDS."})
final class BridgeCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "WORLD", description = "the RobotWorld description")
    private Path world;

    @Option(names = "--space", paramLabel = "URL[,URL...]",
            description = "the space server, or the servers of a clustered space separated by commas (default: "
                    + "rwe.space.url, RWE_SPACE_URL or the world's SpaceURL)")
    private String space;

    @Option(names = "--port", paramLabel = "P", defaultValue = "" + FoxgloveBridge.Options.DEFAULT_PORT,
            description = "TCP port for Foxglove (default: ${DEFAULT-VALUE}; 0 picks a free one)")
    private int port;

    @Option(names = "--bind", paramLabel = "ADDR", defaultValue = "127.0.0.1",
            description = "address to listen on (default: ${DEFAULT-VALUE}; 0.0.0.0 for every interface)")
    private String bind;

    @Option(names = "--token-file", paramLabel = "F",
            description = "file holding a token Foxglove must send (as ?token=... in the URL); default: the space's"
                    + " token (RWE_SPACE_TOKEN or RWE_SPACE_TOKEN_FILE), if set")
    private Path tokenFile;

    @Option(names = "--for", paramLabel = "SECONDS", description = "stop after this many seconds (default: run on)")
    private Double seconds;

    @Option(names = "--schemas", paramLabel = "DIR", description = "validate against the schemas in DIR")
    private Path schemaDirectory;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (seconds != null && !(seconds > 0)) {
            throw new ParameterException(spec.commandLine(), "--for must be positive");
        }
        MonitoredWorld loaded;
        try {
            DescriptionSchemas schemas = schemaDirectory == null ? DescriptionSchemas.configured()
                    : DescriptionSchemas.fromDirectory(schemaDirectory);
            loaded = MonitoredWorld.of(DescriptionLoader.loadWorld(world, schemas));
        } catch (DescriptionException e) {
            e.errors().stream().map(DescriptionError::toString).forEach(err::println);
            return 1;
        }
        WorldLayout layout = WorldLayouts.of(loaded);
        String url = MonitorSpace.url(space, loaded);
        String token = tokenFile != null ? TokenFile.read(tokenFile) : RuntimeSettings.fromSystem().spaceToken();
        FoxgloveBridge.Options options = FoxgloveBridge.Options.defaults().port(port).bindAddress(bind).token(token);
        try (Capi connection = MonitorSpace.open(url);
             FoxgloveBridge bridge = FoxgloveBridge.start(layout, options)) {
            WorldTap tap = new WorldTap(connection, layout).add(bridge.observer());
            SafetyTelemetry safety = null;
            try {
                tap.start();
                safety = SafetyTelemetry.start(connection, bridge::publish);
                out.println("Foxglove endpoint for " + layout.world() + " at " + bridge.uri()
                        + (token != null ? " (token required: add ?token=<token> to the URL)" : ""));
                out.println("watching " + layout.modules().size() + " modules in the space at " + url);
                if (!"127.0.0.1".equals(bind) && !"localhost".equals(bind) && !"::1".equals(bind)) {
                    out.println("warning: reachable from other hosts" + (token == null ? " without a token" : ""));
                }
                out.println("in Foxglove or Lichtblick: Open connection > Foxglove WebSocket > " + bridge.uri()
                        + (seconds == null ? "   (Ctrl-C to stop)" : ""));
                out.flush();
                awaitStop();
            } catch (SpaceException e) {
                err.println("rwe bridge: cannot watch " + layout.world() + " in the space at " + url + ": "
                        + e.getMessage() + " (start it with 'rwe space', or name another with --space URL)");
                return 1;
            } finally {
                tap.close();
                if (safety != null) {
                    safety.close();
                }
            }
            out.println("Foxglove endpoint stopped after " + bridge.published() + " messages"
                    + (bridge.dropped() > 0 ? " (" + bridge.dropped() + " dropped for slow clients)" : ""));
        } catch (IllegalStateException e) {
            endpointFailed(err, "bridge", e, "--port P (0: any free one)");
            return 1;
        }
        return 0;
    }

    /**
     * Says why the Foxglove endpoint (or, for rwe bridge, the command) could not start: the message, and when the
     * port is taken, the fix with {@code portOption}, the option of {@code verb} that chooses it.
     */
    static void endpointFailed(PrintWriter err, String verb, IllegalStateException failure, String portOption) {
        err.println("rwe " + verb + ": " + failure.getMessage());
        for (Throwable cause = failure.getCause(); cause != null; cause = cause.getCause()) {
            if (cause instanceof BindException) {
                err.println("Stop the program that uses it (another rwe bridge or rwe replay?), or choose another port"
                        + " with " + portOption + ".");
                break;
            }
        }
        err.flush();
    }

    private void awaitStop() {
        CountDownLatch stop = new CountDownLatch(1);
        Thread hook = new Thread(stop::countDown, "rwe-bridge-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            if (seconds == null) {
                stop.await();
            } else {
                stop.await(Math.round(seconds * 1000), TimeUnit.MILLISECONDS);
            }
        } catch (InterruptedException e) {
            // stopped from inside the JVM (tests, embedding)
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException e) {
                // shutting down already
            }
        }
    }
}
