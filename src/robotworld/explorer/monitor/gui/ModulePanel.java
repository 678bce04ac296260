package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.GridLayout;
import java.time.Instant;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;

/**
 * The frame every module panel shares: a titled border {@code <Class>: <Name>} (as in the thesis figures), the
 * module-specific body, and a status area with the {@link FreshnessLabel} and the last problem reported (a
 * failed call). Subclasses put their body in with {@link #setBody}. Swing thread only.
 */
public abstract class ModulePanel extends JPanel {

    private static final Color PROBLEM = new Color(0xB0, 0x00, 0x20);

    private final String moduleClass;
    private final String moduleName;
    private final FreshnessLabel freshness = new FreshnessLabel();
    private final JLabel problem = new JLabel(" ");

    protected ModulePanel(String moduleClass, String moduleName) {
        super(new BorderLayout(4, 4));
        this.moduleClass = moduleClass;
        this.moduleName = moduleName;
        setName(moduleClass + ":" + moduleName);
        setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(moduleClass + ": " + moduleName),
                BorderFactory.createEmptyBorder(2, 6, 4, 6)));
        problem.setForeground(PROBLEM);
        JPanel status = new JPanel(new GridLayout(0, 1));
        status.add(freshness);
        status.add(problem);
        add(status, BorderLayout.SOUTH);
        getAccessibleContext().setAccessibleName(moduleClass + " " + moduleName);
    }

    /** Puts the module-specific content in the middle. */
    protected final void setBody(JComponent body) {
        add(body, BorderLayout.CENTER);
    }

    /** The module reported (any answer, also a failed call): updates the freshness line. */
    public void reported(Instant when, String host) {
        freshness.reported(when, host);
    }

    /** The module reported before monitoring started (time unknown), answering {@code host}. */
    public void reportedEarlier(String host) {
        freshness.reportedEarlier(host);
    }

    /** Shows a failed call until the next good report. */
    public void showProblem(String text) {
        problem.setText(text);
        problem.setToolTipText(text);
    }

    /** Clears the problem line (a good report arrived). */
    public void clearProblem() {
        problem.setText(" ");
        problem.setToolTipText(null);
    }

    /** The problem line's text (blank when there is none). */
    public String problemText() {
        return problem.getText().isBlank() ? "" : problem.getText();
    }

    /** The freshness line. */
    public FreshnessLabel freshness() {
        return freshness;
    }

    /** The module's {@code <Class>}. */
    public String moduleClass() {
        return moduleClass;
    }

    /** The module's {@code <Name>}. */
    public String moduleName() {
        return moduleName;
    }
}
