package robotworld.explorer.monitor;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import robotworld.explorer.monitor.gui.ParticipantWindow;
import robotworld.explorer.stop.StopButton;
import robotworld.observe.ReplayMark;
import robotworld.safety.StopRecord;
import robotworld.safety.StopWatcher;
import robotworld.space.Capi;
import robotworld.space.SpaceException;

/**
 * Monitoring of a whole world in windows (thesis 4.2.4): for each participant a {@link ParticipantWindow} with
 * the panel of every module's monitor, loaded by {@link MonitorLoader}, and the world's STOP button at the top of
 * every window. Stops of the world's actuators ({@link StopRecord}s) reach the modules' monitors, whose panels say
 * why. Swing thread only.
 */
public final class WorldMonitor implements AutoCloseable {

    private final List<Monitor> monitors = new ArrayList<>();
    private final List<ParticipantWindow> windows = new ArrayList<>();
    private final List<StopButton> stopButtons = new ArrayList<>();
    private final java.util.Map<String, Monitor> byModule = new java.util.concurrent.ConcurrentHashMap<>();
    private volatile StopWatcher stops;
    private volatile boolean closed;

    /** Builds the monitors and windows (not shown yet: see {@link #show()}). */
    public WorldMonitor(MonitoredWorld world, Capi space, MonitorLoader loader) {
        for (MonitoredParticipant participant : world.participants()) {
            List<JComponent> panels = new ArrayList<>();
            for (MonitoredModule module : participant.modules()) {
                Monitor monitor = loader.load(module, space);
                monitors.add(monitor);
                byModule.put(module.label(), monitor);
                panels.add(monitor.getPanel());
            }
            ParticipantWindow window = new ParticipantWindow(world.name(), participant.name(), participant.kind(),
                    panels);
            StopButton stop = new StopButton("STOP button of the monitor",
                    () -> new StopButton.Scope(world, space.spaceUri().toString(), space));
            window.showAtTop(stop);
            stopButtons.add(stop);
            windows.add(window);
        }
        watchStops(space);
        markReplay(space);
    }

    /** A replayed run says so in every window's title (looked up off the Swing thread: it asks the space). */
    private void markReplay(Capi space) {
        Thread lookup = new Thread(() -> {
            try {
                ReplayMark.find(space).ifPresent(mark -> SwingUtilities.invokeLater(() -> windows.forEach(
                        window -> window.setTitle(mark.label() + " - " + window.getTitle()))));
            } catch (RuntimeException e) {
                // the monitors report an unreachable space on their panels
            }
        }, "monitor-replay-mark");
        lookup.setDaemon(true);
        lookup.start();
    }

    /** Watches the stop records in the background (the Swing thread never waits for the network). */
    private void watchStops(Capi space) {
        Thread starter = new Thread(() -> {
            try {
                StopWatcher watcher = StopWatcher.start(space, this::stopped);
                stops = watcher;
                if (closed) {
                    watcher.close();
                }
            } catch (SpaceException e) {
                // the module panels say that the space cannot be reached
            }
        }, "monitor-stops");
        starter.setDaemon(true);
        starter.start();
    }

    private void stopped(StopRecord record) {
        Monitor monitor = byModule.get(record.participant() + "/" + record.module());
        if (monitor != null) {
            monitor.stopped(record);
        }
    }

    /** The STOP buttons, one per window. */
    public List<StopButton> stopButtons() {
        return List.copyOf(stopButtons);
    }

    /** Shows the windows side by side, cascading from the top left corner. */
    public void show() {
        int offset = 0;
        for (ParticipantWindow window : windows) {
            window.setLocation(offset, offset / 2);
            window.setVisible(true);
            offset += 40 + window.getWidth() / 2;
        }
    }

    /** The windows, one per participant. */
    public List<ParticipantWindow> windows() {
        return List.copyOf(windows);
    }

    /** The monitors, one per module. */
    public List<Monitor> monitors() {
        return List.copyOf(monitors);
    }

    /**
     * Waits until every monitor watches its module (they start in the background). Not on the Swing thread.
     *
     * @return whether all do within {@code timeout} (a monitor that cannot watch says why on its panel)
     */
    public boolean awaitWatching(Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        for (Monitor monitor : List.copyOf(monitors)) {
            if (!monitor.awaitWatching(Duration.ofNanos(Math.max(0, deadline - System.nanoTime())))) {
                return false;
            }
        }
        return true;
    }

    /** Stops every monitor and closes the windows. */
    @Override
    public void close() {
        closed = true;
        StopWatcher watcher = stops;
        if (watcher != null) {
            watcher.close();
        }
        monitors.forEach(Monitor::close);
        windows.forEach(ParticipantWindow::dispose);
    }
}
