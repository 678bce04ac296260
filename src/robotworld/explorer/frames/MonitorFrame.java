package robotworld.explorer.frames;

import java.awt.BorderLayout;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.SwingWorker;
import javax.swing.WindowConstants;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.monitor.MonitorLoader;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldMonitor;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.explorer.stop.StopButton;
import robotworld.space.Capi;

/**
 * "Monitor a world": choose a world file and, optionally, the space URL (blank: the override or the world's
 * {@code <SpaceURL>}), then open the world's monitor window. The
 * STOP button at the top stops every actuator of the chosen world. Connecting runs off the Swing thread.
 */
public final class MonitorFrame extends JFrame {

    /** The window title. */
    public static final String TITLE = "Monitor a world - RobotWorldExplorer";

    private final PathField worldFile = new PathField("", false, 'B');
    private final JTextField spaceUrl = new JTextField(30);
    private final JButton start = Form.button("Open monitors", 'O', event -> start());
    private final Status status = new Status("Choose a world; leave the space URL blank to use the world's.");
    private final List<WorldMonitor> opened = new ArrayList<>();
    private final StopButton stop = new StopButton("STOP button of the monitor frame", this::stopScope);

    public MonitorFrame() {
        super(TITLE);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        Form form = new Form();
        form.row("World file:", 'W', worldFile.textField(), worldFile);
        form.row("Space URL:", 'S', spaceUrl);
        JPanel buttons = new JPanel(new BorderLayout());
        buttons.add(start, BorderLayout.EAST);
        form.wide(buttons);
        getContentPane().add(stop, BorderLayout.NORTH);
        getContentPane().add(form, BorderLayout.CENTER);
        getContentPane().add(status, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(start);
        pack();
    }

    /** The world file field. */
    public JTextField worldFileField() {
        return worldFile.textField();
    }

    /** The space URL field. */
    public JTextField spaceUrlField() {
        return spaceUrl;
    }

    /** The button that opens the monitoring windows. */
    public JButton startButton() {
        return start;
    }

    /** The status line. */
    public String statusText() {
        return status.getText();
    }

    /** The STOP button. */
    public StopButton stopButton() {
        return stop;
    }

    /** The world in the fields, for the STOP button; null (and the status says why) when there is none. */
    private StopButton.Scope stopScope() {
        Path file = worldFile.path();
        if (file == null) {
            status.error("Type or choose the world to stop first.");
            return null;
        }
        try {
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(file, DescriptionSchemas.configured()));
            return new StopButton.Scope(world, MonitorSpace.url(spaceUrl.getText(), world), null);
        } catch (DescriptionException e) {
            status.error("Cannot stop: " + e.errors().size() + " problem(s) in the world, first: " + e.errors().get(0));
        } catch (IllegalStateException e) {
            status.error("Cannot stop: " + e.getMessage());
        }
        return null;
    }

    /** The world monitors opened from this frame. */
    public List<WorldMonitor> opened() {
        return List.copyOf(opened);
    }

    private void start() {
        Path file = worldFile.path();
        if (file == null) {
            status.error("Type or choose a world file first.");
            return;
        }
        MonitoredWorld world;
        String url;
        try {
            world = MonitoredWorld.of(DescriptionLoader.loadWorld(file, DescriptionSchemas.configured()));
            url = MonitorSpace.url(spaceUrl.getText(), world);
        } catch (DescriptionException e) {
            DescriptionError first = e.errors().get(0);
            status.error(e.errors().size() + " problem(s), first: " + first);
            return;
        } catch (IllegalStateException e) {
            status.error(e.getMessage());
            return;
        }
        start.setEnabled(false);
        status.info("Connecting to " + url + "...");
        new SwingWorker<Capi, Void>() {
            @Override
            protected Capi doInBackground() {
                return MonitorSpace.open(url);
            }

            @Override
            protected void done() {
                start.setEnabled(true);
                try {
                    WorldMonitor monitor = new WorldMonitor(world, get(), new MonitorLoader(),
                            WorldMonitor.Windows.ONE, LayoutMemory.fromSettings());
                    opened.add(monitor);
                    monitor.show();
                    status.info("Monitoring " + world.moduleCount() + " modules of " + world.name() + " on " + url);
                } catch (ExecutionException e) {
                    status.error("Cannot connect to " + url + ": " + e.getCause().getMessage());
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
    }
}
