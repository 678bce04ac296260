package robotworld.explorer.frames;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.event.ActionListener;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;

/**
 * A two-column form of labelled fields. Every label has a mnemonic and points at its field
 * ({@code setLabelFor}), so Alt+letter moves the focus to the field and screen readers name it.
 */
final class Form extends JPanel {

    private int row;

    Form() {
        super(new GridBagLayout());
        setBorder(BorderFactory.createEmptyBorder(8, 8, 4, 8));
    }

    /** Adds {@code text} (with {@code mnemonic}) and {@code field} as one row; returns the field. */
    <T extends JComponent> T row(String text, char mnemonic, T field) {
        row(text, mnemonic, field, field);
        return field;
    }

    /** Adds a row whose label points at {@code target}, a part of {@code field} (e.g. a path with its button). */
    JLabel row(String text, char mnemonic, JComponent target, JComponent field) {
        JLabel label = label(text, mnemonic, target);
        GridBagConstraints left = constraints(0, row);
        left.anchor = GridBagConstraints.LINE_START;
        add(label, left);
        GridBagConstraints right = constraints(1, row);
        right.fill = GridBagConstraints.HORIZONTAL;
        right.weightx = 1;
        add(field, right);
        row++;
        return label;
    }

    /** Adds a component across both columns, e.g. a button row or a progress bar. */
    <T extends JComponent> T wide(T component) {
        GridBagConstraints both = constraints(0, row++);
        both.gridwidth = 2;
        both.fill = GridBagConstraints.HORIZONTAL;
        add(component, both);
        return component;
    }

    /** A label with a mnemonic that focuses {@code target}. */
    static JLabel label(String text, char mnemonic, JComponent target) {
        JLabel label = new JLabel(text);
        label.setDisplayedMnemonic(mnemonic);
        label.setLabelFor(target);
        return label;
    }

    /** A button with a mnemonic. */
    static JButton button(String text, char mnemonic, ActionListener action) {
        JButton button = new JButton(text);
        button.setMnemonic(mnemonic);
        button.addActionListener(action);
        return button;
    }

    private static GridBagConstraints constraints(int x, int y) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = x;
        c.gridy = y;
        c.insets = new Insets(3, 3, 3, 3);
        return c;
    }
}
