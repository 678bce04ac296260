package robotworld.explorer.frames;

import java.awt.BorderLayout;
import java.nio.file.Path;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * A path typed in or chosen with a file chooser ("Browse..."). The text field is what a form label points at;
 * the button has its own mnemonic.
 */
final class PathField extends JPanel {

    private final JTextField text;
    private final JButton browse;
    private final boolean directories;

    /**
     * @param initial     the initial path text
     * @param directories choose folders instead of files
     * @param mnemonic    the Browse button's mnemonic
     */
    PathField(String initial, boolean directories, char mnemonic) {
        super(new BorderLayout(4, 0));
        this.directories = directories;
        this.text = new JTextField(initial, 32);
        this.browse = Form.button("Browse...", mnemonic, event -> choose());
        add(text, BorderLayout.CENTER);
        add(browse, BorderLayout.EAST);
    }

    /** The text field (for labels and tests). */
    JTextField textField() {
        return text;
    }

    /** The Browse button. */
    JButton browseButton() {
        return browse;
    }

    /** The path typed or chosen, or null when the field is blank. */
    Path path() {
        String value = text.getText().strip();
        return value.isEmpty() ? null : Path.of(value);
    }

    void setPath(String value) {
        text.setText(value);
    }

    private void choose() {
        JFileChooser chooser = new JFileChooser();
        chooser.setFileSelectionMode(directories ? JFileChooser.DIRECTORIES_ONLY : JFileChooser.FILES_ONLY);
        Path current = path();
        if (current != null) {
            chooser.setSelectedFile(current.toAbsolutePath().toFile());
        }
        if (chooser.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
            text.setText(chooser.getSelectedFile().getPath());
        }
    }
}
