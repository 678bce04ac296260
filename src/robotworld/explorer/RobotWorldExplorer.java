package robotworld.explorer;

import java.awt.BorderLayout;
import java.awt.GridLayout;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.function.Supplier;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import javax.swing.JFileChooser;
import javax.swing.JOptionPane;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.frames.AssembleFrame;
import robotworld.explorer.frames.ExploreFrame;
import robotworld.explorer.frames.GenerateFrame;
import robotworld.explorer.frames.MonitorFrame;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.stop.StopButton;

/**
 * The RobotWorldExplorer launcher (thesis figure 4.1): a main window with the steps from robot to running world,
 * explore a robot, assemble a world, generate a framework, monitor a world; each opens its own window. Start it
 * with {@code ./antw run}, or {@code rwe} without a verb on a desktop. Below them, always visible, the STOP button
 * stops every actuator of a world: the first click asks which world (a RobotWorld file), later clicks stop the same
 * one at once.
 */
public final class RobotWorldExplorer extends JFrame {

    /** The main window's title. */
    public static final String TITLE = "RobotWorldExplorer";

    private final Path home;
    private final JButton explore;
    private final JButton assemble;
    private final JButton generate;
    private final JButton monitor;
    private final StopButton stop;
    private final JLabel stopWorld = new JLabel("STOP asks for the world to stop the first time.");
    private volatile StopButton.Scope stopScope;

    /** The main window; {@code home} holds {@code ModuleDescriptions/} and receives robot descriptions. */
    public RobotWorldExplorer(Path home) {
        super(TITLE);
        this.home = home;
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        explore = choice("Explore a robot", 'E', () -> new ExploreFrame(this.home));
        assemble = choice("Assemble a world", 'A', () -> new AssembleFrame(this.home));
        generate = choice("Generate a framework", 'G', GenerateFrame::new);
        monitor = choice("Monitor a world", 'M', MonitorFrame::new);
        JPanel buttons = new JPanel(new GridLayout(1, 4, 12, 0));
        buttons.add(explore);
        buttons.add(assemble);
        buttons.add(generate);
        buttons.add(monitor);
        JPanel content = new JPanel(new BorderLayout(0, 10));
        content.setBorder(BorderFactory.createEmptyBorder(14, 14, 14, 14));
        content.add(new JLabel("<html>Describe the robots and environments of a RobotWorld, generate a control"
                + " framework for any of its computers,<br>and watch the modules at work.</html>"), BorderLayout.NORTH);
        content.add(buttons, BorderLayout.CENTER);
        stop = new StopButton("STOP button of the launcher", this::stopScope);
        JButton change = new JButton("World to stop...");
        change.setMnemonic('W');
        change.addActionListener(event -> chooseWorldToStop());
        JPanel stopBar = new JPanel(new BorderLayout(8, 4));
        stopBar.add(stop, BorderLayout.NORTH);
        stopBar.add(stopWorld, BorderLayout.CENTER);
        stopBar.add(change, BorderLayout.EAST);
        content.add(stopBar, BorderLayout.SOUTH);
        setContentPane(content);
        pack();
        setLocationRelativeTo(null);
    }

    /** Starts the launcher; closing its main window ends the program. */
    public static void main(String[] args) {
        SwingUtilities.invokeLater(() -> {
            RobotWorldExplorer launcher = new RobotWorldExplorer(defaultHome());
            launcher.setDefaultCloseOperation(WindowConstants.EXIT_ON_CLOSE);
            launcher.setVisible(true);
        });
    }

    /**
     * Shows the launcher and waits until its main window is closed (for the {@code rwe} command line, which
     * exits afterwards).
     */
    public static void showAndWait() throws InterruptedException {
        CountDownLatch closed = new CountDownLatch(1);
        SwingUtilities.invokeLater(() -> {
            RobotWorldExplorer launcher = new RobotWorldExplorer(defaultHome());
            launcher.addWindowListener(new WindowAdapter() {
                @Override
                public void windowClosed(WindowEvent event) {
                    closed.countDown();
                }
            });
            launcher.setVisible(true);
        });
        closed.await();
    }

    /** {@code rwe.home}, else the working directory. */
    public static Path defaultHome() {
        return Path.of(System.getProperty("rwe.home", ".")).toAbsolutePath().normalize();
    }

    /** The "Explore a robot" button. */
    public JButton exploreButton() {
        return explore;
    }

    /** The "Assemble a world" button. */
    public JButton assembleButton() {
        return assemble;
    }

    /** The "Generate a framework" button. */
    public JButton generateButton() {
        return generate;
    }

    /** The "Monitor a world" button. */
    public JButton monitorButton() {
        return monitor;
    }

    /** The STOP button. */
    public StopButton stopButton() {
        return stop;
    }

    /** Sets the world the STOP button stops (its space: the override or the world's {@code <SpaceURL>}). */
    public void setWorldToStop(MonitoredWorld world, String spaceUrl) {
        stopScope = new StopButton.Scope(world, spaceUrl, null);
        stopWorld.setText("STOP stops every actuator of " + world.name() + " through " + spaceUrl);
    }

    private StopButton.Scope stopScope() {
        if (stopScope == null) {
            chooseWorldToStop();
        }
        return stopScope;
    }

    private void chooseWorldToStop() {
        JFileChooser chooser = new JFileChooser(home.toFile());
        chooser.setDialogTitle("The RobotWorld to stop");
        if (chooser.showOpenDialog(this) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        try {
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(chooser.getSelectedFile().toPath(),
                    DescriptionSchemas.configured()));
            setWorldToStop(world, MonitorSpace.url(null, world));
        } catch (DescriptionException e) {
            JOptionPane.showMessageDialog(this, e.errors().get(0).toString(), "Not a valid RobotWorld",
                    JOptionPane.ERROR_MESSAGE);
        } catch (IllegalStateException e) {
            JOptionPane.showMessageDialog(this, e.getMessage(), "No space to stop it through",
                    JOptionPane.ERROR_MESSAGE);
        }
    }

    private static JButton choice(String text, char mnemonic, Supplier<JFrame> window) {
        JButton button = new JButton(text);
        button.setMnemonic(mnemonic);
        button.addActionListener(event -> {
            JFrame frame = window.get();
            frame.setLocationByPlatform(true);
            frame.setVisible(true);
        });
        return button;
    }
}
