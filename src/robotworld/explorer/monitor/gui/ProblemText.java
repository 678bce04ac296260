package robotworld.explorer.monitor.gui;

import java.awt.Dimension;
import java.awt.Insets;
import javax.swing.JTextArea;
import javax.swing.UIManager;

/**
 * A problem message that wraps at whatever width its panel gives it and always takes {@value #ROWS} lines: its
 * preferred width is minimal and its height fixed, so a long message never widens or stretches the panel; what
 * does not fit is cut, and the tooltip has it all. Read-only; copyable.
 */
final class ProblemText extends JTextArea {

    /** Lines shown. */
    static final int ROWS = 2;

    ProblemText() {
        super(ROWS, 1);
        setEditable(false);
        setLineWrap(true);
        setWrapStyleWord(true);
        setOpaque(false);
        setBorder(null);
        setFocusable(false);
        setFont(UIManager.getFont("Label.font"));
        getAccessibleContext().setAccessibleName("problem");
    }

    /** Shows {@code text} (empty: none). */
    void show(String text) {
        setText(text);
        setCaretPosition(0);
        setToolTipText(text.isEmpty() ? null : text);
    }

    @Override
    public Dimension getPreferredSize() {
        Insets insets = getInsets();
        return new Dimension(40, ROWS * getRowHeight() + insets.top + insets.bottom);
    }

    @Override
    public Dimension getMinimumSize() {
        return getPreferredSize();
    }

    @Override
    public Dimension getMaximumSize() {
        return new Dimension(Integer.MAX_VALUE, getPreferredSize().height);
    }
}
