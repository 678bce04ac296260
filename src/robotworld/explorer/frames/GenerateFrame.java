package robotworld.explorer.frames;

import java.awt.BorderLayout;
import java.awt.GridLayout;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.List;
import javax.swing.AbstractButton;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JRadioButton;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextField;
import javax.swing.JTree;
import javax.swing.WindowConstants;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.FrameworkGenerator;
import robotworld.explorer.generator.GenerationResult;
import robotworld.explorer.generator.RunInstructions;
import robotworld.explorer.monitor.MonitoredParticipant;
import robotworld.explorer.monitor.MonitoredWorld;

/**
 * "Generate a framework" (thesis figure 4.4): load a world (validation errors listed with line and column), see
 * it as a tree, choose the viewpoint (a participant or external), the package and the destination folder, and
 * Generate. Generation runs off the Swing thread; the result shows the project's path and main class.
 */
public final class GenerateFrame extends JFrame {

    /** The window title. */
    public static final String TITLE = "Generate a framework - RobotWorldExplorer";

    private static final String NO_WORLD = "load a valid world first";

    private final PathField worldFile = new PathField("", false, 'B');
    private final JButton load = Form.button("Load", 'L', event -> loadWorld());
    private final LogArea errors = new LogArea(4, 60);
    private final JTree tree = new JTree(WorldTree.empty());
    private final JPanel viewpoints = new JPanel(new GridLayout(0, 1));
    private final ButtonGroup viewpointGroup = new ButtonGroup();
    private final JTextField packageName = new JTextField(20);
    private final PathField destination = new PathField("", true, 'r');
    private final JCheckBox replace = new JCheckBox("Replace an existing project in that folder");
    private final JButton generate = Form.button("Generate", 'G', event -> startGeneration());
    private final JProgressBar progress = new JProgressBar();
    private final JTextField result = new JTextField(50);
    private final Status status = new Status("Load a RobotWorld description.");
    private final javax.swing.JLabel viewpointLabel;
    private RobotWorldDocument world;
    private String generatedViewpoint;

    public GenerateFrame() {
        super(TITLE);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        Form top = new Form();
        JPanel fileRow = new JPanel(new BorderLayout(4, 0));
        fileRow.add(worldFile, BorderLayout.CENTER);
        fileRow.add(load, BorderLayout.EAST);
        top.row("World file:", 'W', worldFile.textField(), fileRow);
        errors.getAccessibleContext().setAccessibleName("validation errors");
        errors.setLineWrap(true);
        top.row("Validation errors:", 'E', errors, new JScrollPane(errors));

        Form options = new Form();
        viewpoints.setBorder(BorderFactory.createEtchedBorder());
        viewpoints.add(new javax.swing.JLabel(NO_WORLD));
        viewpointLabel = options.row("Viewpoint:", 'V', viewpoints, viewpoints);
        options.row("Package name:", 'P', packageName);
        options.row("Destination folder:", 'D', destination.textField(), destination);
        replace.setMnemonic('x');
        options.wide(replace);
        JPanel buttonRow = new JPanel(new BorderLayout());
        buttonRow.add(generate, BorderLayout.EAST);
        options.wide(buttonRow);
        progress.setStringPainted(true);
        progress.setString("");
        options.wide(progress);
        result.setEditable(false);
        options.row("Result:", 'u', result);

        tree.getAccessibleContext().setAccessibleName("the world's participants and modules");
        JScrollPane treeView = new JScrollPane(tree);
        treeView.setBorder(BorderFactory.createTitledBorder("World"));
        JPanel left = new JPanel(new BorderLayout());
        left.add(options, BorderLayout.NORTH);
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left, treeView);
        split.setResizeWeight(0.6);

        getContentPane().add(top, BorderLayout.NORTH);
        getContentPane().add(split, BorderLayout.CENTER);
        getContentPane().add(status, BorderLayout.SOUTH);
        generate.setEnabled(false);
        getRootPane().setDefaultButton(load);
        pack();
    }

    // ---- accessors for the launcher and tests ----

    /** The world file field. */
    public JTextField worldFileField() {
        return worldFile.textField();
    }

    /** The Load button. */
    public JButton loadButton() {
        return load;
    }

    /** The validation errors shown, one per line ({@code file:line:column: message}). */
    public String errorsText() {
        return errors.getText();
    }

    /** The world tree. */
    public JTree tree() {
        return tree;
    }

    /** The viewpoint radio buttons, participants first, then external. */
    public List<JRadioButton> viewpointButtons() {
        List<JRadioButton> buttons = new ArrayList<>();
        for (Enumeration<AbstractButton> all = viewpointGroup.getElements(); all.hasMoreElements(); ) {
            buttons.add((JRadioButton) all.nextElement());
        }
        return buttons;
    }

    /** The package name field. */
    public JTextField packageNameField() {
        return packageName;
    }

    /** The destination folder field. */
    public JTextField destinationField() {
        return destination.textField();
    }

    /** The Generate button. */
    public JButton generateButton() {
        return generate;
    }

    /** The result line: the project's path and main class after a generation. */
    public String resultText() {
        return result.getText();
    }

    /** The progress bar's text: the step being done, "done" or "failed" (empty before the first generation). */
    public String progressText() {
        return progress.getString();
    }

    /** The status line. */
    public String statusText() {
        return status.getText();
    }

    /** Loads the world named in the world file field (as the Load button does). */
    public void loadWorld() {
        errors.setText("");
        result.setText(""); // the last generation was of the world loaded before
        progress.setValue(0);
        progress.setString("");
        Path file = worldFile.path();
        if (file == null) {
            status.error("Type or choose a world file first.");
            return;
        }
        try {
            RobotWorldDocument loaded = DescriptionLoader.loadWorld(file, DescriptionSchemas.configured());
            show(loaded);
            status.info("Loaded " + file + ". Choose a viewpoint and a destination, then Generate.");
        } catch (DescriptionException e) {
            world = null;
            generate.setEnabled(false);
            tree.setModel(WorldTree.empty()); // never show the previous world next to this one's errors
            viewpoints.removeAll();
            viewpoints.add(new javax.swing.JLabel(NO_WORLD));
            viewpoints.revalidate();
            e.errors().stream().map(DescriptionError::toString).forEach(errors::line);
            errors.setCaretPosition(0);
            status.error(e.errors().size() + " problem(s) in " + file + " (listed above)");
        }
    }

    private void show(RobotWorldDocument loaded) {
        world = loaded;
        MonitoredWorld summary = MonitoredWorld.of(loaded);
        tree.setModel(WorldTree.of(summary));
        for (int row = 0; row < tree.getRowCount(); row++) {
            tree.expandRow(row);
        }
        viewpoints.removeAll();
        viewpointGroup.clearSelection();
        for (AbstractButton old : viewpointButtons()) {
            viewpointGroup.remove(old);
        }
        for (MonitoredParticipant participant : summary.participants()) {
            addViewpoint(participant.name(), participant.name() + " (" + participant.kind() + ")");
        }
        addViewpoint(FrameworkGenerator.EXTERNAL, "external (a computer without hardware)");
        viewpointButtons().get(0).setSelected(true);
        viewpointLabel.setLabelFor(viewpointButtons().get(0)); // Alt+V goes to the radio buttons
        String declared = loaded.getRobotWorld().isSetPackageName() ? loaded.getRobotWorld().getPackageName()
                : summary.name().toLowerCase(java.util.Locale.ROOT);
        packageName.setText(declared);
        generate.setEnabled(true);
        getRootPane().setDefaultButton(generate);
        viewpoints.revalidate();
        pack();
    }

    private void addViewpoint(String name, String text) {
        JRadioButton button = new JRadioButton(text);
        button.setActionCommand(name);
        button.getAccessibleContext().setAccessibleName("viewpoint " + text);
        viewpointGroup.add(button);
        viewpoints.add(button);
    }

    private void startGeneration() {
        if (world == null) {
            status.error("Load a world first.");
            return;
        }
        Path folder = destination.path();
        if (folder == null || viewpointGroup.getSelection() == null) {
            status.error("Choose a viewpoint and a destination folder.");
            return;
        }
        String chosenPackage = packageName.getText().strip();
        generate.setEnabled(false);
        result.setText("");
        progress.setValue(0);
        progress.setString("starting");
        status.info("Generating...");
        generatedViewpoint = viewpointGroup.getSelection().getActionCommand();
        new GenerateWorker(this, world, generatedViewpoint,
                chosenPackage.isEmpty() ? null : chosenPackage, folder, replace.isSelected()).execute();
    }

    void stepped(int done, int total, String text) {
        progress.setMaximum(total);
        progress.setValue(done);
        progress.setString(text);
    }

    void generated(GenerationResult generated) {
        generate.setEnabled(true);
        progress.setValue(progress.getMaximum());
        progress.setString("done");
        result.setText(generated.destination().toString());
        result.setCaretPosition(0);
        status.info("Generated " + generated.files().size() + " files; main class " + generated.mainClass()
                + ". Write your program in control(), then run: " + RunInstructions.command(world, generatedViewpoint,
                generated.destination()));
    }

    void failed(String message) {
        generate.setEnabled(true);
        progress.setString("failed");
        status.error(message);
    }
}
