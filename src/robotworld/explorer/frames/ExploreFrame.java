package robotworld.explorer.frames;

import java.awt.BorderLayout;
import java.nio.file.Path;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import robotworld.bus.explore.RobotExplorer;

/**
 * "Explore a robot" (thesis figure 4.3): port (detected serial ports, or typed: a device path or
 * {@code tcp://host:port}), robot name, destination folder, Explore. A progress bar follows the 247 bus
 * addresses and the log shows what is found; the work runs off the Swing thread.
 */
public final class ExploreFrame extends JFrame {

    /** The window title. */
    public static final String TITLE = "Explore a robot - RobotWorldExplorer";

    private final JComboBox<String> port = new JComboBox<>(SerialPortChoices.detected().toArray(String[]::new));
    private final JTextField robotName = new JTextField("MyRobot", 20);
    private final PathField destination;
    private final JButton explore = Form.button("Explore", 'E', event -> start());
    private final JProgressBar progress = new JProgressBar(0, RobotExplorer.LAST_ADDRESS);
    private final LogArea log = new LogArea(10, 60);
    private final Status status = new Status("Choose the robot's port and press Explore.");
    private final Path catalogFolder;

    /**
     * @param home the RobotWorldExplorer home: module descriptions are read from {@code home/ModuleDescriptions},
     *             robot descriptions go to {@code home/RobotDescriptions} unless another folder is chosen
     */
    public ExploreFrame(Path home) {
        super(TITLE);
        this.catalogFolder = home.resolve("ModuleDescriptions");
        this.destination = new PathField(home.resolve("RobotDescriptions").toString(), true, 'B');
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        port.setEditable(true);
        Form form = new Form();
        form.row("Port:", 'P', port);
        form.row("Robot name:", 'N', robotName);
        form.row("Destination folder:", 'D', destination.textField(), destination);
        JPanel buttons = new JPanel(new BorderLayout());
        buttons.add(explore, BorderLayout.EAST);
        form.wide(buttons);
        progress.setStringPainted(true);
        progress.setString("not started");
        progress.getAccessibleContext().setAccessibleName("bus addresses explored");
        form.wide(progress);
        log.getAccessibleContext().setAccessibleName("exploration log");
        getContentPane().add(form, BorderLayout.NORTH);
        getContentPane().add(new JScrollPane(log), BorderLayout.CENTER);
        getContentPane().add(status, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(explore);
        pack();
    }

    /** The port field (editable). */
    public JComboBox<String> portField() {
        return port;
    }

    /** The robot name field. */
    public JTextField robotNameField() {
        return robotName;
    }

    /** The destination folder field. */
    public JTextField destinationField() {
        return destination.textField();
    }

    /** The Explore button. */
    public JButton exploreButton() {
        return explore;
    }

    /** The progress bar over the bus addresses. */
    public JProgressBar progress() {
        return progress;
    }

    /** The status line's text. */
    public String statusText() {
        return status.getText();
    }

    /** The log's text. */
    public String logText() {
        return log.getText();
    }

    LogArea log() {
        return log;
    }

    private void start() {
        Object chosen = port.getEditor().getItem();
        String portName = chosen == null ? "" : chosen.toString().strip();
        String name = robotName.getText().strip();
        Path folder = destination.path();
        if (portName.isEmpty() || name.isEmpty() || folder == null) {
            status.error("Give a port, a robot name and a destination folder.");
            return;
        }
        explore.setEnabled(false);
        log.setText(""); // a new exploration: the last one's lines would be taken for this one's
        progress.setValue(0);
        progress.setString("starting");
        status.info("Exploring " + portName + "...");
        new ExploreWorker(this, portName, name, folder.resolve(name + ".xml"), catalogFolder).execute();
    }

    /** From the exploring thread: moves the progress bar on the Swing thread. */
    void progressLater(int address, int done, int total) {
        SwingUtilities.invokeLater(() -> {
            progress.setMaximum(total);
            progress.setValue(done);
            progress.setString("address " + address + " (" + done + " of " + total + ")");
        });
    }

    /** The exploration ended: {@code outcome} says how. Swing thread. */
    void finished(String outcome, boolean failed) {
        explore.setEnabled(true);
        if (failed) {
            progress.setString("failed");
            status.error(outcome);
        } else {
            progress.setValue(progress.getMaximum());
            progress.setString("done");
            status.info(outcome);
        }
    }
}
