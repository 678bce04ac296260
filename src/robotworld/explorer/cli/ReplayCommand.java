package robotworld.explorer.cli;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
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
import robotworld.explorer.monitor.ConsoleMonitor;
import robotworld.explorer.monitor.MonitorLoader;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldMonitor;
import robotworld.observe.WorldTap;
import robotworld.recording.Replayer;
import robotworld.recording.mcap.McapFormatException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.server.SpaceServer;
import robotworld.telemetry.SafetyTelemetry;

/**
 * {@code rwe replay FILE.mcap [--rate R] [--loop]}: plays a recording into a space of its own, so monitors and
 * Foxglove show the run again; drives no hardware.
 */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = {"Replay a recording (see docs/recording.md) into a space of its own: monitors (rwe monitor",
                "WORLD --space URL, or --console / --windows here) and Foxglove show the run as it happened,",
                "marked as a replay. Nothing serves the replayed calls, so no hardware moves.",
                "Ends when the recording does (--loop: never; --hold: keep serving until Ctrl-C)."})
final class ReplayCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "FILE.mcap", description = "the recording")
    private Path file;

    @Option(names = "--rate", paramLabel = "R", defaultValue = "1",
            description = "speed: 1 as recorded (default), 2 twice as fast, 0.5 half as fast")
    private double rate;

    @Option(names = "--loop", description = "start again at the end, until Ctrl-C")
    private boolean loop;

    @Option(names = "--hold", description = "keep serving the space after the end, until Ctrl-C")
    private boolean hold;

    @Option(names = "--port", paramLabel = "P", defaultValue = "0",
            description = "the replay space's TCP port (default: a free one, so no program of a live world finds it)")
    private int port;

    @Option(names = "--bind", paramLabel = "ADDR", defaultValue = "127.0.0.1",
            description = "address to listen on (default: ${DEFAULT-VALUE})")
    private String bind;

    @Option(names = "--token-file", paramLabel = "F",
            description = "file holding a token clients of the replay space and endpoint must send")
    private Path tokenFile;

    @Option(names = "--foxglove-port", paramLabel = "P", defaultValue = "" + FoxgloveBridge.Options.DEFAULT_PORT,
            description = "port of the Foxglove endpoint (default: ${DEFAULT-VALUE}; 0 a free one; -1 none)")
    private int foxglovePort;

    @Option(names = "--console", description = "show the console monitor here")
    private boolean console;

    @Option(names = "--windows", description = "open the monitor windows here (needs a display)")
    private boolean windows;

    @Option(names = "--world", paramLabel = "FILE",
            description = "the world's description, when the recording does not carry it (for the monitors)")
    private Path worldFile;

    @Option(names = {"-q", "--quiet"}, description = "no progress line")
    private boolean quiet;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Replayer.Options options;
        try {
            options = new Replayer.Options(rate, loop);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "--rate: " + e.getMessage());
        }
        if (windows && GraphicsEnvironment.isHeadless()) {
            err.println("rwe replay: no display here; use --console for a text view");
            return 1;
        }
        Replayer replayer;
        try {
            replayer = Replayer.open(file);
        } catch (java.nio.file.NoSuchFileException e) {
            err.println("rwe replay: no such file: " + file);
            return 1;
        } catch (McapFormatException e) {
            err.println("rwe replay: " + e.getMessage());
            return 1;
        }
        try (replayer) {
            MonitoredWorld world;
            Path description;
            try {
                description = description(replayer);
                world = description == null ? null : MonitoredWorld.of(DescriptionLoader.loadWorld(description));
            } catch (DescriptionException e) {
                e.errors().stream().map(DescriptionError::toString).forEach(err::println);
                return 1;
            }
            if ((console || windows) && world == null) {
                err.println("rwe replay: the recording does not carry its world's description; give it with --world"
                        + " FILE to use the monitors");
                return 1;
            }
            String token = tokenFile != null ? TokenFile.read(tokenFile) : RuntimeSettings.fromSystem().spaceToken();
            SpaceServer.Options serverOptions = SpaceServer.Options.defaults().port(port).bindAddress(bind);
            if (token != null) {
                serverOptions = serverOptions.token(token);
            }
            try (SpaceServer server = SpaceServer.start(serverOptions)) {
                return serve(replayer, options, server, world, description, token, out, err);
            }
        }
    }

    private int serve(Replayer replayer, Replayer.Options options, SpaceServer server, MonitoredWorld world,
            Path description, String token, PrintWriter out, PrintWriter err) throws Exception {
        out.printf(Locale.ROOT, "replaying %s: %d messages over %.1f s of %s, at %sx%s%n", file,
                replayer.playable(), replayer.length().toMillis() / 1000.0, replayer.layout().world(),
                rate == Math.rint(rate) ? String.valueOf((long) rate) : String.valueOf(rate), loop ? ", looping" : "");
        out.println("replay space at " + server.uri() + (token != null ? " (token required)" : ""));
        if (description != null) {
            out.println("watch it: rwe monitor " + description + " --space " + server.uri());
        }
        FoxgloveBridge bridge = null;
        WorldTap bridgeTap = null;
        SafetyTelemetry bridgeSafety = null;
        ConsoleMonitor consoleMonitor = null;
        AtomicReference<WorldMonitor> windowMonitor = new AtomicReference<>();
        Thread player = Thread.currentThread();
        CountDownLatch done = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            player.interrupt();
            try {
                done.await(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "rwe-replay-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            replayer.prepare(server.space(), options); // the views started next see the replay mark
            if (foxglovePort >= 0) {
                try {
                    bridge = FoxgloveBridge.start(replayer.layout(), FoxgloveBridge.Options.defaults()
                            .port(foxglovePort).bindAddress(bind).token(token));
                } catch (IllegalStateException e) {
                    // --port is the replay space's: name the endpoint's own option
                    BridgeCommand.endpointFailed(err, "replay", e, "--foxglove-port P (0: any free one; -1: none)");
                    return 1;
                }
                bridgeTap = new WorldTap(server.space(), replayer.layout()).add(bridge.observer()).start();
                bridgeSafety = SafetyTelemetry.start(server.space(), bridge::publish);
                out.println("Foxglove endpoint at " + bridge.uri());
            }
            if (console) {
                consoleMonitor = new ConsoleMonitor(world, server.space(), out);
            }
            if (windows) {
                SwingUtilities.invokeAndWait(() -> {
                    windowMonitor.set(new WorldMonitor(world, server.space(), new MonitorLoader()));
                    windowMonitor.get().show();
                });
            }
            out.flush();
            long started = System.nanoTime();
            long[] lastLine = {System.nanoTime()};
            try {
                replayer.play(server.space(), options, progress -> {
                    long now = System.nanoTime();
                    if (!quiet && now - lastLine[0] >= 1_000_000_000L) {
                        lastLine[0] = now;
                        err.printf(Locale.ROOT, "\rpass %d: %d/%d messages, %.1f of %.1f s recorded time%s",
                                progress.pass(), progress.played(), progress.total(),
                                progress.position().toMillis() / 1000.0, progress.length().toMillis() / 1000.0,
                                progress.skipped() > 0 ? ", " + progress.skipped() + " unreadable" : "");
                        err.flush();
                    }
                });
            } catch (SpaceInterruptedException ctrlC) {
                Thread.currentThread().interrupt(); // Ctrl-C while a call to the replay space waited: a stop too
            } catch (java.nio.channels.ClosedByInterruptException ctrlC) {
                Thread.currentThread().interrupt(); // Ctrl-C while the recording was being read: a stop too
            }
            boolean interrupted = Thread.interrupted();
            if (!quiet) {
                err.printf(Locale.ROOT, "%nreplay %s after %.1f s%n", interrupted ? "stopped" : "finished",
                        (System.nanoTime() - started) / 1e9);
            }
            if (hold && !interrupted) {
                out.println("holding the replay space at " + server.uri() + "; Ctrl-C to stop");
                out.flush();
                try {
                    new CountDownLatch(1).await();
                } catch (InterruptedException e) {
                    // Ctrl-C
                }
            }
            return 0;
        } finally {
            if (consoleMonitor != null) {
                pauseThroughInterrupts(200); // the last answers reach the console, even after a late Ctrl-C
                consoleMonitor.close();
            }
            if (windowMonitor.get() != null) {
                SwingUtilities.invokeAndWait(() -> windowMonitor.get().close());
            }
            if (bridgeTap != null) {
                bridgeTap.close();
            }
            if (bridgeSafety != null) {
                bridgeSafety.close();
            }
            if (bridge != null) {
                bridge.close();
            }
            done.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException e) {
                // shutting down already
            }
        }
    }

    /** Sleeps {@code millis}, interrupted or not; an interrupt is kept for the caller. */
    private static void pauseThroughInterrupts(long millis) {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        boolean interrupted = false;
        for (long left; (left = end - System.nanoTime()) > 0; ) {
            try {
                TimeUnit.NANOSECONDS.sleep(left);
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /** --world, or the description the recording carries written to a temporary file, or null. */
    private Path description(Replayer replayer) throws IOException {
        if (worldFile != null) {
            return worldFile;
        }
        byte[] xml = replayer.worldDescription().orElse(null);
        if (xml == null) {
            return null;
        }
        Path folder = Files.createTempDirectory("rwe-replay");
        folder.toFile().deleteOnExit(); // files are deleted at exit in reverse order: the file, then its folder
        Path written = folder.resolve(replayer.layout().world() + ".xml");
        written.toFile().deleteOnExit();
        Files.write(written, xml);
        return written;
    }
}
