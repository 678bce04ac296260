package robotworld.explorer.frames;

import java.awt.Color;
import javax.swing.JLabel;

/** The one-line status at the bottom of a frame: what happened last, red when it is an error. */
final class Status extends JLabel {

    private static final Color ERROR = new Color(0xB0, 0x00, 0x20);

    Status(String initial) {
        super(initial);
        getAccessibleContext().setAccessibleName("status");
    }

    void info(String text) {
        setForeground(null);
        setText(text);
    }

    void error(String text) {
        setForeground(ERROR);
        setText(text);
    }
}
