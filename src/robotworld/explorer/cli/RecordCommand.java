package robotworld.explorer.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldLayouts;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldTap;
import robotworld.recording.Recorder;
import robotworld.recording.RecordingInfo;
import robotworld.recording.mcap.McapFormatException;
import robotworld.space.Capi;
import robotworld.space.SpaceException;
import robotworld.telemetry.SafetyTelemetry;

/**
 * {@code rwe record WORLD --out FILE.mcap [--duration S]}: records a running world's traffic as MCAP, with a
 * progress line, until Ctrl-C or the duration; {@code rwe record --info FILE.mcap} says what a recording holds.
 */
@Command(name = "record", mixinStandardHelpOptions = true,
        description = {"Record a running RobotWorld's traffic into an MCAP file (see docs/recording.md): "
                + "every module's requests, answers and errors, participant liveness, stops, gaps, and the "
                + "simulated robots' ground truth. Ends on Ctrl-C or after --duration, leaving a finished file.",
                "With --info FILE: print what a recording holds (channels, counts, time range)."})
final class RecordCommand implements Callable<Integer> {

    @Parameters(index = "0", arity = "0..1", paramLabel = "WORLD", description = "the RobotWorld description")
    private Path world;

    @Option(names = "--out", paramLabel = "FILE.mcap", description = "the recording to write (replaced if it exists)")
    private Path out;

    @Option(names = "--duration", paramLabel = "S", description = "stop after this many seconds (default: Ctrl-C)")
    private Double duration;

    @Option(names = "--space", paramLabel = "URL[,URL...]",
            description = "the space server, or the servers of a clustered space separated by commas (default: "
                    + "rwe.space.url, RWE_SPACE_URL or the world's SpaceURL)")
    private String space;

    @Option(names = "--info", paramLabel = "FILE.mcap", description = "print what a recording holds, record nothing")
    private Path info;

    @Option(names = "--schemas", paramLabel = "DIR", description = "validate against the schemas in DIR")
    private Path schemaDirectory;

    @Option(names = {"-q", "--quiet"}, description = "no progress line")
    private boolean quiet;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter stdout = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (info != null) {
            if (world != null || out != null) {
                throw new ParameterException(spec.commandLine(), "--info FILE takes no WORLD and no --out");
            }
            try {
                RecordingInfo.of(info).print(stdout);
                return 0;
            } catch (java.nio.file.NoSuchFileException e) {
                err.println("rwe record: no such file: " + info);
                return 1;
            } catch (McapFormatException e) {
                err.println("rwe record: " + info + ": " + e.getMessage());
                return 1;
            }
        }
        if (world == null || out == null) {
            throw new ParameterException(spec.commandLine(), "give WORLD and --out FILE.mcap (or --info FILE.mcap)");
        }
        if (duration != null && !(duration > 0)) {
            throw new ParameterException(spec.commandLine(), "--duration must be positive");
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
        Recorder recorder;
        try {
            recorder = Recorder.start(out, new Recorder.Start(layout, url, Files.readAllBytes(world)),
                    Recorder.Options.defaults());
        } catch (IOException e) {
            err.println("rwe record: cannot write " + out + ": " + e.getMessage());
            return 1;
        }
        // Ctrl-C: the hook stops the recording and holds the JVM until the file is finished and the summary printed
        CountDownLatch stop = new CountDownLatch(1);
        CountDownLatch finished = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            stop.countDown();
            try {
                finished.await(20, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "rwe-record-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            return record(recorder, layout, url, stop, stdout, err);
        } finally {
            stdout.flush();
            err.flush();
            finished.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException e) {
                // shutting down already
            }
        }
    }

    /** Records until {@code stop}, the duration or a failure, and prints the summary. Returns the exit code. */
    private int record(Recorder recorder, WorldLayout layout, String url, CountDownLatch stop, PrintWriter stdout,
            PrintWriter err) throws IOException {
        try (Capi connection = MonitorSpace.open(url)) {
            WorldTap tap = new WorldTap(connection, layout);
            tap.add(recorder.observer());
            SafetyTelemetry safety = null;
            try {
                tap.start();
                safety = SafetyTelemetry.start(connection, recorder::offer);
            } catch (SpaceException e) {
                tap.close();
                recorder.close("the space could not be watched");
                Files.deleteIfExists(out); // nothing was recorded: leave nothing behind
                err.println("rwe record: cannot watch " + layout.world() + " in the space at " + url + ": "
                        + e.getMessage() + " (start it with 'rwe space', or name another with --space URL)");
                return 1;
            }
            err.println("recording " + layout.modules().size() + " modules of " + layout.world() + " from " + url
                    + " into " + out + (duration == null ? "; Ctrl-C to stop" : " for " + duration + " s"));
            err.flush();
            try {
                String why = awaitEnd(recorder, err, stop);
                tap.close();
                recorder.close(why);
            } finally {
                tap.close();
                safety.close();
            }
        } catch (SpaceException e) {
            boolean empty = recorder.status().messages() == 0;
            recorder.close("the space could not be reached");
            if (empty) {
                Files.deleteIfExists(out);
            }
            err.println("rwe record: cannot reach the space at " + url + ": " + e.getMessage()
                    + " (start it with 'rwe space', or name another with --space URL)");
            return 1;
        }
        Recorder.Status status = recorder.status();
        err.println();
        stdout.println("recorded " + status.messages() + " messages, " + Progress.bytes(status.bytes()) + " in "
                + Progress.seconds(status.elapsed()) + " into " + out + "; " + (status.dropped() == 0
                ? "nothing dropped" : status.dropped() + " messages dropped (the recorder or the tap fell behind;"
                + " see /rwe/gaps in the file)"));
        if (status.failure() != null) {
            err.println("rwe record: " + status.failure());
            return 1;
        }
        return 0;
    }

    /** Until Ctrl-C, the duration, a write failure or an interrupt; prints progress. Returns why it ended. */
    private String awaitEnd(Recorder recorder, PrintWriter err, CountDownLatch stop) {
        long end = duration == null ? Long.MAX_VALUE : System.nanoTime() + Math.round(duration * 1e9);
        try {
            while (true) {
                long left = end - System.nanoTime();
                if (left <= 0) {
                    return "--duration reached";
                }
                if (stop.await(Math.min(left, TimeUnit.SECONDS.toNanos(1)), TimeUnit.NANOSECONDS)) {
                    return "Ctrl-C";
                }
                Recorder.Status status = recorder.status();
                if (status.failure() != null) {
                    return status.failure();
                }
                if (!quiet) {
                    err.print("\r" + Progress.line(status));
                    err.flush();
                }
            }
        } catch (InterruptedException e) {
            return "interrupted";
        }
    }

    /** Formats the progress line. */
    static final class Progress {
        private Progress() {
        }

        static String line(Recorder.Status status) {
            return String.format(java.util.Locale.ROOT, "%s  %d messages  %s  %s dropped%s%s",
                    seconds(status.elapsed()), status.messages(), bytes(status.bytes()), status.dropped(),
                    status.queued() > 0 ? "  " + status.queued() + " waiting" : "",
                    status.behind() ? "  FALLING BEHIND" : "      ");
        }

        static String seconds(Duration elapsed) {
            return String.format(java.util.Locale.ROOT, "%.1f s", elapsed.toMillis() / 1000.0);
        }

        static String bytes(long bytes) {
            if (bytes < 1024) {
                return bytes + " B";
            }
            if (bytes < 1024 * 1024) {
                return String.format(java.util.Locale.ROOT, "%.1f KiB", bytes / 1024.0);
            }
            return String.format(java.util.Locale.ROOT, "%.1f MiB", bytes / (1024.0 * 1024));
        }
    }
}
