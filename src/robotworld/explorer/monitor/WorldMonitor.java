package robotworld.explorer.monitor;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.explorer.monitor.gui.MonitorLook;
import robotworld.explorer.monitor.gui.MonitorWindow;
import robotworld.explorer.monitor.gui.ParticipantPanel;
import robotworld.explorer.monitor.gui.ParticipantWindow;
import robotworld.explorer.monitor.gui.PlotsPanel;
import robotworld.explorer.monitor.gui.StatusStrip;
import robotworld.explorer.monitor.gui.WorldView;
import robotworld.observe.AnswerSeen;
import robotworld.observe.GroundTruth;
import robotworld.observe.ReplayMark;
import robotworld.observe.WorldObserver;
import robotworld.observe.WorldTap;
import robotworld.explorer.stop.StopButton;
import robotworld.safety.StopRecord;
import robotworld.safety.StopWatcher;
import robotworld.space.Capi;
import robotworld.space.SpaceException;

/**
 * Monitoring of a whole world in windows (thesis 4.2.4, extended): one {@link WorldTap} reads the world's traffic
 * and feeds the monitor of every module (loaded by {@link MonitorLoader}), the plots, the status strip and the
 * world view. By default everything is in one {@link MonitorWindow}; the thesis's one window per participant
 * ({@link ParticipantWindow}) remains available. The world's STOP button is at the top of every window, and stops
 * of the world's actuators ({@link StopRecord}s) reach the modules' monitors, whose panels say why. Swing thread
 * only.
 */
public final class WorldMonitor implements AutoCloseable {

    /** How the monitor is laid out. */
    public enum Windows {
        /** One window: world view, plots, a tab per participant, status strip. */
        ONE,
        /** One window per participant with its module panels (the thesis's layout). */
        PER_PARTICIPANT
    }

    private final WorldTap tap;
    private final PlotModel plots;
    private final TrafficStatistics statistics;
    private final RobotReadings readings;
    private final List<Monitor> monitors = new ArrayList<>();
    private final List<ParticipantWindow> windows = new ArrayList<>();
    private final MonitorWindow window;
    private final List<StopButton> stopButtons = new ArrayList<>();
    private final Map<String, Monitor> byModule = new ConcurrentHashMap<>();
    private volatile StopWatcher stops;
    private volatile boolean closed;

    /** One window, remembering nothing: see {@link #WorldMonitor(MonitoredWorld, Capi, MonitorLoader, Windows, LayoutMemory)}. */
    public WorldMonitor(MonitoredWorld world, Capi space, MonitorLoader loader) {
        this(world, space, loader, Windows.ONE, LayoutMemory.none());
    }

    /**
     * Builds the monitors and windows (not shown yet: see {@link #show()}) and starts watching in the background.
     *
     * @param memory where the one window's layout is remembered
     */
    public WorldMonitor(MonitoredWorld world, Capi space, MonitorLoader loader, Windows layout, LayoutMemory memory) {
        MonitorLook.install();
        tap = new WorldTap(space, world.layout());
        plots = new PlotModel(world.layout());
        statistics = new TrafficStatistics(world.layout());
        readings = new RobotReadings(world.layout());
        tap.add(statistics).add(plots).add(readings);
        WorldView view = new WorldView(readings);
        tap.add(new WorldObserver() {
            @Override
            public void groundTruth(GroundTruth frame) {
                view.show(frame);
            }

            @Override
            public void answerSeen(AnswerSeen event) {
                view.readingsChanged();
            }
        });
        List<ParticipantPanel> tabs = new ArrayList<>();
        for (MonitoredParticipant participant : world.participants()) {
            List<JComponent> panels = new ArrayList<>();
            for (MonitoredModule module : participant.modules()) {
                Monitor monitor = loader.load(module, space, tap);
                monitors.add(monitor);
                byModule.put(module.label(), monitor);
                panels.add(monitor.getPanel());
            }
            if (layout == Windows.PER_PARTICIPANT) {
                ParticipantWindow each = new ParticipantWindow(world.name(), participant.name(), participant.kind(),
                        panels);
                each.showAtTop(stopButton(world, space));
                windows.add(each);
            } else {
                tabs.add(new ParticipantPanel(participant.name(), participant.kind(), panels));
            }
        }
        window = layout == Windows.ONE ? new MonitorWindow(world.name(), tabs, view, new PlotsPanel(plots,
                world.layout().robots().collect(java.util.stream.Collectors.toSet())),
                new StatusStrip(statistics), memory) : null;
        if (window != null) {
            window.showAtTop(stopButton(world, space));
        }
        tap.startInBackground();
        watchStops(space);
        markReplay(space);
    }

    /**
     * A replayed run says so in every window's title and in a banner at its top (looked up off the Swing thread:
     * it asks the space).
     */
    private void markReplay(Capi space) {
        Thread lookup = new Thread(() -> {
            try {
                ReplayMark.find(space).ifPresent(mark -> SwingUtilities.invokeLater(() -> {
                    List<javax.swing.JFrame> frames = new ArrayList<>(windows);
                    if (window != null) {
                        frames.add(window);
                    }
                    frames.forEach(frame -> markReplay(frame, mark));
                }));
            } catch (RuntimeException e) {
                // the monitors report an unreachable space on their panels
            }
        }, "monitor-replay-mark");
        lookup.setDaemon(true);
        lookup.start();
    }

    /** The title, and a banner above what the window shows at its top (the STOP button stays). */
    private static void markReplay(javax.swing.JFrame frame, ReplayMark mark) {
        frame.setTitle(mark.label() + " - " + frame.getTitle());
        javax.swing.JLabel banner = new javax.swing.JLabel(mark.label() + ": a recorded run, nothing is driven");
        banner.setName("replay-banner");
        banner.setOpaque(true);
        banner.setBackground(new java.awt.Color(0xFF, 0xE0, 0x80));
        banner.setBorder(javax.swing.BorderFactory.createEmptyBorder(4, 6, 4, 6));
        java.awt.Container content = frame.getContentPane();
        javax.swing.JPanel top = new javax.swing.JPanel(new java.awt.BorderLayout());
        top.add(banner, java.awt.BorderLayout.NORTH);
        if (content.getLayout() instanceof java.awt.BorderLayout border) {
            java.awt.Component north = border.getLayoutComponent(java.awt.BorderLayout.NORTH);
            if (north != null) {
                content.remove(north);
                top.add(north, java.awt.BorderLayout.CENTER);
            }
        }
        content.add(top, java.awt.BorderLayout.NORTH);
        content.revalidate();
        frame.repaint();
    }

    private StopButton stopButton(MonitoredWorld world, Capi space) {
        StopButton stop = new StopButton("STOP button of the monitor",
                () -> new StopButton.Scope(world, space.spaceUri().toString(), space));
        stopButtons.add(stop);
        return stop;
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

    /** The STOP buttons: one in the window, or one per participant's window. */
    public List<StopButton> stopButtons() {
        return List.copyOf(stopButtons);
    }

    /** Shows the window, or the participants' windows side by side, cascading from the top left corner. */
    public void show() {
        if (window != null) {
            window.setVisible(true);
            return;
        }
        int offset = 0;
        for (ParticipantWindow each : windows) {
            each.setLocation(offset, offset / 2);
            each.setVisible(true);
            offset += 40 + each.getWidth() / 2;
        }
    }

    /** The one window, or null when laid out per participant. */
    public MonitorWindow window() {
        return window;
    }

    /** The participants' windows (empty in the one-window layout). */
    public List<ParticipantWindow> windows() {
        return List.copyOf(windows);
    }

    /** The monitors, one per module. */
    public List<Monitor> monitors() {
        return List.copyOf(monitors);
    }

    /** The tap feeding everything. */
    public WorldTap tap() {
        return tap;
    }

    /** The values behind the plots. */
    public PlotModel plotModel() {
        return plots;
    }

    /** The figures behind the status strip. */
    public TrafficStatistics statistics() {
        return statistics;
    }

    /**
     * Waits until everything watches (it starts in the background). Not on the Swing thread.
     *
     * @return whether all do within {@code timeout} (a monitor that cannot watch says why on its panel)
     */
    public boolean awaitWatching(Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        if (!tap.awaitWatching(timeout)) {
            return false;
        }
        for (Monitor monitor : List.copyOf(monitors)) {
            if (!monitor.awaitWatching(Duration.ofNanos(Math.max(0, deadline - System.nanoTime())))) {
                return false;
            }
        }
        return true;
    }

    /** Stops watching and closes the windows (the one window remembers its layout). */
    @Override
    public void close() {
        closed = true;
        StopWatcher watcher = stops;
        if (watcher != null) {
            watcher.close();
        }
        monitors.forEach(Monitor::close);
        tap.close();
        windows.forEach(ParticipantWindow::dispose);
        if (window != null) {
            window.dispose();
        }
    }
}
