package robotworld.explorer.cli;

import java.awt.GraphicsEnvironment;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.Callable;
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
import robotworld.explorer.monitor.gui.ParticipantWindow;
import robotworld.space.Capi;

/**
 * {@code rwe monitor WORLD [--space URL] [--console] [--for SECONDS]}: watches every module of a running world,
 * in one window per participant or, with {@code --console}, as text lines.
 */
@Command(name = "monitor", mixinStandardHelpOptions = true,
        description = {"Watch every module of a running RobotWorld, in windows or as text.",
                "Opens one window per participant; with --console prints one line per call instead",
                "(time, participant, module, function, value, host).",
                "Runs until the windows are closed, Ctrl-C, or --for SECONDS have passed."})
final class MonitorCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "WORLD", description = "the RobotWorld description")
    private Path world;

    @Option(names = "--space", paramLabel = "URL",
            description = "the space server (default: rwe.space.url, RWE_SPACE_URL or the world's SpaceURL)")
    private String space;

    @Option(names = "--console", description = "print a live text view instead of opening windows (headless)")
    private boolean console;

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
        if (!console && GraphicsEnvironment.isHeadless()) {
            err.println("rwe monitor: no display here; use --console for a text view");
            return 1;
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
        String url = MonitorSpace.url(space, loaded);
        try (Capi connection = MonitorSpace.open(url)) {
            return console ? watchAsText(loaded, connection, url, out, err) : watchInWindows(loaded, connection, err);
        }
    }

    private int watchAsText(MonitoredWorld loaded, Capi connection, String url, PrintWriter out, PrintWriter err)
            throws InterruptedException {
        try (ConsoleMonitor monitor = new ConsoleMonitor(loaded, connection, out)) {
            err.println("monitoring " + monitor.moduleCount() + " modules of " + loaded.name() + " on " + url
                    + (seconds == null ? "; Ctrl-C to stop" : " for " + seconds + " s"));
            err.flush();
            awaitStop(new CountDownLatch(1));
        }
        return 0;
    }

    private int watchInWindows(MonitoredWorld loaded, Capi connection, PrintWriter err) throws Exception {
        AtomicReference<WorldMonitor> monitor = new AtomicReference<>();
        CountDownLatch allClosed = new CountDownLatch(Math.max(1, loaded.participants().size()));
        SwingUtilities.invokeAndWait(() -> {
            WorldMonitor opened = new WorldMonitor(loaded, connection, new MonitorLoader());
            for (ParticipantWindow window : opened.windows()) {
                window.addWindowListener(new java.awt.event.WindowAdapter() {
                    @Override
                    public void windowClosed(java.awt.event.WindowEvent event) {
                        allClosed.countDown();
                    }
                });
            }
            monitor.set(opened);
            opened.show();
        });
        err.println("monitoring " + loaded.moduleCount() + " modules of " + loaded.name()
                + "; close the windows or press Ctrl-C to stop");
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
