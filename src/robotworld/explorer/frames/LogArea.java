package robotworld.explorer.frames;

import java.awt.Font;
import javax.swing.JTextArea;

/** A read-only, focusable text area that collects log lines and keeps the newest in view. Swing thread only. */
final class LogArea extends JTextArea {

    LogArea(int rows, int columns) {
        super(rows, columns);
        setEditable(false);
        setFont(new Font(Font.MONOSPACED, Font.PLAIN, getFont().getSize()));
    }

    void append(String line, boolean newline) {
        super.append(newline ? line + "\n" : line);
        setCaretPosition(getDocument().getLength());
    }

    void line(String line) {
        append(line, true);
    }
}
