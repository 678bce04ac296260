package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.time.Instant;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;

/**
 * The frame every module panel shares: a titled border {@code <Class>: <Name>} (as in the thesis figures), the
 * module-specific body, and a status area with the {@link FreshnessLabel}, the last problem reported (a failed
 * call), whether notifications were missed (a gap in the space's notification stream) and, for an actuator put
 * into its safe state, who stopped it, when and why. Subclasses put their body in with {@link #setBody}. Swing
 * thread only.
 */
public abstract class ModulePanel extends JPanel {

    private static final Color PROBLEM = new Color(0xB0, 0x00, 0x20);

    private final String moduleClass;
    private final String moduleName;
    private final FreshnessLabel freshness = new FreshnessLabel();
    private final ProblemText problem = new ProblemText();
    private final JLabel stop = new JLabel();
    private final JLabel gap = new JLabel();
    private int gaps;

    protected ModulePanel(String moduleClass, String moduleName) {
        super(new BorderLayout(4, 4));
        this.moduleClass = moduleClass;
        this.moduleName = moduleName;
        setName(moduleClass + ":" + moduleName);
        setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(moduleClass + ": " + moduleName),
                BorderFactory.createEmptyBorder(2, 6, 4, 6)));
        problem.setForeground(PROBLEM);
        JPanel status = new JPanel(new BorderLayout());
        status.add(freshness, BorderLayout.NORTH);
        status.add(problem, BorderLayout.CENTER);
        stop.setForeground(PROBLEM);
        stop.setName("stop");
        stop.setVisible(false);
        gap.setForeground(PROBLEM);
        gap.setName("gap");
        gap.setVisible(false);
        JPanel lower = new JPanel();
        lower.setLayout(new javax.swing.BoxLayout(lower, javax.swing.BoxLayout.Y_AXIS)); // hidden lines take no room
        lower.add(gap);
        lower.add(stop);
        status.add(lower, BorderLayout.SOUTH);
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

    /**
     * Shows a failed call until the module is called again or reports well: wrapped within the panel's width on at most
     * {@value ProblemText#ROWS} lines (the whole text in the tooltip), so that however long, it never changes the
     * layout.
     */
    public void showProblem(String text) {
        problem.show(text);
    }

    /** Clears the problem line (a good report arrived, or a new call is under way). */
    public void clearProblem() {
        problem.show("");
    }

    /**
     * Shows that notifications of this module may have been missed at {@code when}; the line stays (with a count),
     * since the answers shown around that moment may not be the whole story.
     */
    public void showGap(Instant when, String why) {
        gaps++;
        String at = java.time.format.DateTimeFormatter.ofPattern("HH:mm:ss")
                .format(java.time.LocalTime.ofInstant(when, java.time.ZoneId.systemDefault()));
        gap.setText(gaps == 1 ? "notifications missed at " + at : "notifications missed " + gaps + "x, last at " + at);
        gap.setToolTipText(why);
        gap.setVisible(true);
        revalidate();
    }

    /** The gap line's text (empty when no notification was missed). */
    public String gapText() {
        return gap.isVisible() ? gap.getText() : "";
    }

    /** Shows that the module was put into its safe state, and why, until it is commanded again. */
    public void showStopped(String text) {
        stop.setText("STOPPED " + text);
        stop.setToolTipText(stop.getText());
        // the line is as wide as the panel, not as its text: the whole reason is in the tooltip
        stop.setPreferredSize(new java.awt.Dimension(1, stop.getPreferredSize().height));
        stop.setVisible(true);
        revalidate();
    }

    /** The module was commanded again: the stop line goes. */
    public void clearStopped() {
        if (stop.isVisible()) {
            stop.setVisible(false);
            stop.setText("");
            revalidate();
        }
    }

    /** The stop line's text (empty when the module was not stopped since it was last commanded). */
    public String stoppedText() {
        return stop.isVisible() ? stop.getText() : "";
    }

    /** The problem line's text (blank when there is none). */
    public String problemText() {
        return problem.getText().isBlank() ? "" : problem.getText();
    }

    /** The problem area (for tests of the layout). */
    public JComponent problemArea() {
        return problem;
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
