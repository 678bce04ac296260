package robotworld.explorer.frames;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.DefaultCellEditor;
import javax.swing.DefaultListModel;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.ListSelectionModel;
import javax.swing.WindowConstants;
import javax.swing.table.DefaultTableModel;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionSummary;
import robotworld.description.EnvironmentBuilder;
import robotworld.description.EnvironmentBuilder.X10Device;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.WorldAssembly;

/**
 * "Assemble a world", the step between exploring robots and generating frameworks (what {@code rwe assemble}
 * does): pick the robot descriptions, optionally an environment file, add the environment's X10 devices in a
 * table, name the world and Save. Errors are listed as {@code file:line:column: message}; after saving, "Generate a
 * framework" opens the next step with the new world loaded.
 */
public final class AssembleFrame extends JFrame {

    /** The window title. */
    public static final String TITLE = "Assemble a world - RobotWorldExplorer";

    private static final String[] COLUMNS = {"Address (A1..P16)", "Kind", "Module name"};

    private final Path home;
    private final JTextField worldName = new JTextField("MyWorld", 20);
    private final DefaultListModel<Path> robotFiles = new DefaultListModel<>();
    private final JList<Path> robots = new JList<>(robotFiles);
    private final JButton addRobot = Form.button("Add...", 'A', event -> chooseRobots());
    private final JButton removeRobot = Form.button("Remove", 'm', event -> removeRobots());
    private final PathField environmentFile = new PathField("", false, 'B');
    private final JTextField environmentName = new JTextField("Room", 20);
    private final JTextField environmentHost = new JTextField(20);
    private final JTextField cm11aPort = new JTextField(EnvironmentBuilder.DEFAULT_CM11A_PORT, 20);
    private final DefaultTableModel deviceRows = new DefaultTableModel(COLUMNS, 0);
    private final JTable devices = new JTable(deviceRows);
    private final JButton addDevice = Form.button("Add device", 'D', event -> addDeviceRow("A1", "lamp", ""));
    private final JButton removeDevice = Form.button("Remove device", 'v', event -> removeDeviceRows());
    private final JTextField spaceUrl = new JTextField(WorldAssembly.DEFAULT_SPACE_URL, 30);
    private final JTextField packageName = new JTextField(20);
    private final PathField output = new PathField("", false, 'o');
    private final JCheckBox replace = new JCheckBox("Replace an existing file");
    private final JButton save = Form.button("Save", 'S', event -> save());
    private final JButton generateNext = Form.button("Generate a framework...", 'G', event -> openGenerate());
    private final LogArea errors = new LogArea(5, 70);
    private final Status status = new Status("Add the robot descriptions (rwe explore writes them), then Save.");
    private Path saved;

    /** @param home the RobotWorldExplorer home: robot descriptions are looked for in {@code home/RobotDescriptions} */
    public AssembleFrame(Path home) {
        super(TITLE);
        this.home = home;
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        Form form = new Form();
        form.row("World name:", 'W', worldName);

        robots.setVisibleRowCount(3);
        robots.setSelectionMode(ListSelectionModel.MULTIPLE_INTERVAL_SELECTION);
        robots.getAccessibleContext().setAccessibleName("robot descriptions");
        JPanel robotRow = new JPanel(new BorderLayout(4, 0));
        robotRow.add(new JScrollPane(robots), BorderLayout.CENTER);
        JPanel robotButtons = new JPanel(new java.awt.GridLayout(2, 1, 0, 4));
        robotButtons.add(addRobot);
        robotButtons.add(removeRobot);
        robotRow.add(top(robotButtons), BorderLayout.EAST);
        form.row("Robot descriptions:", 'R', robots, robotRow);
        form.row("Environment file (optional):", 'E', environmentFile.textField(), environmentFile);

        Form environment = new Form();
        environment.setBorder(BorderFactory.createTitledBorder("An environment with X10 devices (optional)"));
        environment.row("Environment name:", 'N', environmentName);
        environmentHost.setToolTipText("the computer that runs the environment's program; blank: this computer");
        environment.row("Its computer (host):", 'H', environmentHost);
        cm11aPort.setToolTipText("/dev/ttyUSB0, COM4 or tcp://HOST:PORT; programs can override it at run time");
        environment.row("CM11A port:", 'C', cm11aPort);
        JComboBox<String> kinds = new JComboBox<>(new String[] {"lamp", "appliance"});
        devices.getColumnModel().getColumn(1).setCellEditor(new DefaultCellEditor(kinds));
        devices.setPreferredScrollableViewportSize(new java.awt.Dimension(420, 80));
        devices.getAccessibleContext().setAccessibleName("X10 devices");
        devices.putClientProperty("terminateEditOnFocusLost", Boolean.TRUE);
        JPanel deviceRow = new JPanel(new BorderLayout(4, 0));
        deviceRow.add(new JScrollPane(devices), BorderLayout.CENTER);
        JPanel deviceButtons = new JPanel(new java.awt.GridLayout(2, 1, 0, 4));
        deviceButtons.add(addDevice);
        deviceButtons.add(removeDevice);
        deviceRow.add(top(deviceButtons), BorderLayout.EAST);
        environment.row("Devices:", 'i', devices, deviceRow);
        form.wide(environment);

        form.row("Space URL:", 'U', spaceUrl);
        form.row("Package (optional):", 'P', packageName);
        form.row("Write to:", 'T', output.textField(), output);
        replace.setMnemonic('x');
        form.wide(replace);
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.TRAILING));
        buttons.add(save);
        buttons.add(generateNext);
        generateNext.setEnabled(false);
        form.wide(buttons);
        errors.getAccessibleContext().setAccessibleName("errors");
        errors.setLineWrap(true);
        form.row("Errors found:", 'f', errors, new JScrollPane(errors));

        getContentPane().add(form, BorderLayout.CENTER);
        getContentPane().add(status, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(save);
        pack();
    }

    /** Buttons at the top of their column, at their own height. */
    private static JPanel top(JPanel buttons) {
        JPanel column = new JPanel(new BorderLayout());
        column.add(buttons, BorderLayout.NORTH);
        return column;
    }

    // ---- accessors for the launcher and tests ----

    public JTextField worldNameField() {
        return worldName;
    }

    /** Adds a robot description file to the list (as Add... does). */
    public void addRobotFile(Path file) {
        if (!robotFiles.contains(file)) {
            robotFiles.addElement(file);
        }
    }

    public JTextField environmentFileField() {
        return environmentFile.textField();
    }

    public JTextField environmentNameField() {
        return environmentName;
    }

    public JTextField environmentHostField() {
        return environmentHost;
    }

    public JTextField cm11aPortField() {
        return cm11aPort;
    }

    /** Adds a row to the device table: address (A3), kind (lamp or appliance), module name (may be blank). */
    public void addDeviceRow(String address, String kind, String name) {
        if (devices.isEditing()) {
            devices.getCellEditor().stopCellEditing();
        }
        deviceRows.addRow(new Object[] {address, kind, name});
    }

    public JTable deviceTable() {
        return devices;
    }

    public JTextField spaceUrlField() {
        return spaceUrl;
    }

    public JTextField outputField() {
        return output.textField();
    }

    public JCheckBox replaceBox() {
        return replace;
    }

    public JButton saveButton() {
        return save;
    }

    public JButton generateButton() {
        return generateNext;
    }

    public String errorsText() {
        return errors.getText();
    }

    public String statusText() {
        return status.getText();
    }

    // ---- actions ----

    private void chooseRobots() {
        JFileChooser chooser = new JFileChooser(home.resolve("RobotDescriptions").toFile());
        chooser.setMultiSelectionEnabled(true);
        chooser.setDialogTitle("Robot descriptions");
        if (chooser.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
            for (java.io.File file : chooser.getSelectedFiles()) {
                addRobotFile(file.toPath());
            }
        }
    }

    private void removeRobots() {
        for (Path file : robots.getSelectedValuesList()) {
            robotFiles.removeElement(file);
        }
    }

    private void removeDeviceRows() {
        if (devices.isEditing()) {
            devices.getCellEditor().stopCellEditing();
        }
        int[] selected = devices.getSelectedRows();
        for (int i = selected.length - 1; i >= 0; i--) {
            deviceRows.removeRow(selected[i]);
        }
    }

    /** Assembles, validates and writes the world (as Save does). */
    public void save() {
        if (devices.isEditing()) {
            devices.getCellEditor().stopCellEditing();
        }
        errors.setText("");
        saved = null; // "Generate a framework..." opens only what this Save writes
        generateNext.setEnabled(false);
        String name = worldName.getText().strip();
        String problem = WorldAssembly.problemWithName(name);
        if (problem != null) {
            status.error("World name: " + problem);
            return;
        }
        if (robotFiles.isEmpty()) {
            status.error("Add at least one robot description (rwe explore or \"Explore a robot\" writes them).");
            return;
        }
        Path file = output.path() != null ? output.path() : home.resolve("RobotWorlds").resolve(name + ".xml");
        if (Files.exists(file) && !replace.isSelected()) {
            status.error(file + " exists; choose another file or tick \"Replace an existing file\".");
            return;
        }
        List<X10Device> x10 = new ArrayList<>();
        for (int row = 0; row < deviceRows.getRowCount(); row++) {
            String address = String.valueOf(deviceRows.getValueAt(row, 0)).strip();
            String kind = String.valueOf(deviceRows.getValueAt(row, 1)).strip();
            Object moduleName = deviceRows.getValueAt(row, 2);
            String spec = address + "=" + kind + (moduleName == null || moduleName.toString().isBlank() ? ""
                    : ":" + moduleName.toString().strip());
            try {
                x10.add(X10Device.parse(spec));
            } catch (IllegalArgumentException e) {
                status.error("Device in row " + (row + 1) + ": " + e.getMessage());
                return;
            }
        }
        WorldAssembly assembly = new WorldAssembly(name).spaceUrl(spaceUrl.getText())
                .packageName(packageName.getText()).robots(List.of(toArray()));
        if (environmentFile.path() != null) {
            assembly.environments(List.of(environmentFile.path()));
        }
        if (!x10.isEmpty()) {
            String environment = environmentName.getText().strip();
            String environmentProblem = WorldAssembly.problemWithName(environment);
            if (environmentProblem != null) {
                status.error("Environment name: " + environmentProblem);
                return;
            }
            assembly.x10Environment(environment, environmentHost.getText(), cm11aPort.getText(), x10);
        }
        try {
            RobotWorldDocument world = assembly.assemble();
            WorldAssembly.write(world, file);
            saved = file;
            output.setPath(file.toString());
            generateNext.setEnabled(true);
            status.info("Saved " + file + ": " + DescriptionSummary.of(world) + ". Next: Generate a framework.");
        } catch (DescriptionException e) {
            e.errors().stream().map(DescriptionError::toString).forEach(errors::line);
            errors.setCaretPosition(0);
            status.error(e.errors().size() + " problem(s) (listed above); nothing was saved.");
        } catch (IOException e) {
            status.error("Cannot write " + file + ": " + e.getMessage());
        }
    }

    private Path[] toArray() {
        Path[] files = new Path[robotFiles.size()];
        robotFiles.copyInto(files);
        return files;
    }

    private void openGenerate() {
        if (saved == null) {
            return;
        }
        GenerateFrame next = new GenerateFrame();
        next.worldFileField().setText(saved.toString());
        next.loadWorld();
        next.setLocationByPlatform(true);
        next.setVisible(true);
    }
}
