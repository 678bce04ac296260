package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
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
import robotworld.explorer.monitor.ConsoleMonitor;
import robotworld.explorer.monitor.MonitorLoader;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldMonitor;
import robotworld.explorer.monitor.gui.Display;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.space.Capi;

/**
 * {@code rwe monitor WORLD [--space URL] [--console [--changes-only | --compact]] [--module NAME]... [--for S]}:
 * watches the modules of a running world, in the monitor window or as text lines.
 */
@Command(name = "monitor", mixinStandardHelpOptions = true,
        description = {"Watch the modules of a running RobotWorld, in a window or as text.",
                "Opens one window: the world view (robots, rays, bumpers), plots over time, a tab per participant",
                "and a status strip. With --console prints one line per call instead (time, participant, module,",
                "function, value, host), or only changes, or one line per second.",
                "Runs until the window is closed, Ctrl-C, or --for SECONDS have passed."})
final class MonitorCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "WORLD", description = "the RobotWorld description")
    private Path world;

    @Option(names = "--space", paramLabel = "URL[,URL...]",
            description = "the space server, or the servers of a clustered space separated by commas (default: "
                    + "rwe.space.url, RWE_SPACE_URL or the world's SpaceURL)")
    private String space;

    @Option(names = "--console", description = "print a live text view instead of opening a window (headless)")
    private boolean console;

    @Option(names = "--module", paramLabel = "NAME",
            description = "watch only this module (its Name, or Participant/Name); repeatable")
    private List<String> modules = new ArrayList<>();

    @Option(names = "--changes-only", description = "console: print a call only when its value changed")
    private boolean changesOnly;

    @Option(names = "--compact", description = "console: one line per second (calls, last answers, who is alive)")
    private boolean compact;

    @Option(names = "--window-per-participant",
            description = "one window per participant with its module panels, as in the thesis, instead of one")
    private boolean perParticipant;

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
        if (seconds != null && seconds <= 0) {
            throw new ParameterException(spec.commandLine(), "--for must be positive");
        }
        if (!console && (changesOnly || compact)) {
            throw new ParameterException(spec.commandLine(), "--changes-only and --compact are for --console");
        }
        if (changesOnly && compact) {
            throw new ParameterException(spec.commandLine(), "choose --changes-only or --compact, not both");
        }
        if (!console && Display.problem() != null) {
            err.println("rwe monitor: " + Display.problem() + "; use --console for a text view");
            return 1;
        }
        MonitoredWorld loaded;
        try {
            DescriptionSchemas schemas = schemaDirectory == null ? DescriptionSchemas.configured()
                    : DescriptionSchemas.fromDirectory(schemaDirectory);
            loaded = MonitoredWorld.of(DescriptionLoader.loadWorld(world, schemas)).only(modules);
        } catch (DescriptionException e) {
            e.errors().stream().map(DescriptionError::toString).forEach(err::println);
            return 1;
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "--module: " + e.getMessage());
        }
        String url = MonitorSpace.url(space, loaded);
        try (Capi connection = MonitorSpace.open(url)) {
            return console ? watchAsText(loaded, connection, url, out, err) : watchInWindows(loaded, connection, err);
        }
    }

    private int watchAsText(MonitoredWorld loaded, Capi connection, String url, PrintWriter out, PrintWriter err)
            throws InterruptedException {
        try (ConsoleMonitor monitor = new ConsoleMonitor(loaded, connection, out,
                new ConsoleMonitor.Options(changesOnly, compact))) {
            err.println("monitoring " + monitor.moduleCount() + " modules of " + loaded.name() + " on " + url
                    + (seconds == null ? "; Ctrl-C to stop" : " for " + seconds + " s"));
            err.flush();
            awaitStop(new CountDownLatch(1));
        }
        return 0;
    }

    private int watchInWindows(MonitoredWorld loaded, Capi connection, PrintWriter err) throws Exception {
        AtomicReference<WorldMonitor> monitor = new AtomicReference<>();
        WorldMonitor.Windows layout = perParticipant ? WorldMonitor.Windows.PER_PARTICIPANT : WorldMonitor.Windows.ONE;
        List<JFrame> frames = new ArrayList<>();
        SwingUtilities.invokeAndWait(() -> {
            WorldMonitor opened = new WorldMonitor(loaded, connection, new MonitorLoader(), layout,
                    LayoutMemory.fromSettings());
            if (opened.window() != null) {
                frames.add(opened.window());
            }
            frames.addAll(opened.windows());
            monitor.set(opened);
        });
        CountDownLatch allClosed = new CountDownLatch(Math.max(1, frames.size()));
        SwingUtilities.invokeAndWait(() -> {
            for (JFrame frame : frames) {
                frame.addWindowListener(new java.awt.event.WindowAdapter() {
                    @Override
                    public void windowClosed(java.awt.event.WindowEvent event) {
                        allClosed.countDown();
                    }
                });
            }
            monitor.get().show();
        });
        err.println("monitoring " + loaded.moduleCount() + " modules of " + loaded.name()
                + "; close the window" + (frames.size() > 1 ? "s" : "") + " or press Ctrl-C to stop");
        err.flush();
        try {
            awaitStop(allClosed);
        } finally {
            SwingUtilities.invokeAndWait(() -> monitor.get().close());
        }
        return 0;
    }

    /** Until {@code done}, --for SECONDS, an interrupt, or Ctrl-C (which ends the JVM and with it the view). */
    private void awaitStop(CountDownLatch done) throws InterruptedException {
        try {
            if (seconds == null) {
                done.await();
            } else {
                done.await(Math.round(seconds * 1000), TimeUnit.MILLISECONDS);
            }
        } catch (InterruptedException e) {
            // stopped from inside the JVM (tests, embedding): end as --for would
        }
    }
}
