package robotworld.explorer.monitor.gui;

import java.awt.Color;
import java.awt.FlowLayout;
import java.awt.Font;
import javax.swing.ButtonGroup;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JRadioButton;

/**
 * On/off radio buttons (thesis figures 4.8, 4.9) that only display: the user cannot switch the device from a
 * monitor, so the buttons are disabled and a bold word repeats the state in colour. The state is unknown until
 * the first report, since X10 devices cannot be asked.
 */
public final class OnOffIndicator extends JPanel {

    /** What the indicator can show. */
    public enum State { UNKNOWN, ON, OFF }

    private static final Color ON_COLOUR = new Color(0x00, 0x80, 0x20);

    private final JRadioButton on = new JRadioButton("On");
    private final JRadioButton off = new JRadioButton("Off");
    private final ButtonGroup group = new ButtonGroup();
    private final JLabel word = new JLabel("unknown");
    private State state = State.UNKNOWN;

    public OnOffIndicator() {
        super(new FlowLayout(FlowLayout.LEFT, 8, 0));
        group.add(on);
        group.add(off);
        on.setEnabled(false);
        off.setEnabled(false);
        word.setFont(word.getFont().deriveFont(Font.BOLD));
        word.getAccessibleContext().setAccessibleName("state");
        add(on);
        add(off);
        add(word);
    }

    /** Shows the device switched on or off. */
    public void showOn(boolean switchedOn) {
        state = switchedOn ? State.ON : State.OFF;
        (switchedOn ? on : off).setSelected(true);
        word.setText(switchedOn ? "ON" : "OFF");
        word.setForeground(switchedOn ? ON_COLOUR : Color.DARK_GRAY);
    }

    /** What is shown. */
    public State state() {
        return state;
    }

    /** The word shown next to the buttons: {@code ON}, {@code OFF} or {@code unknown}. */
    public String stateText() {
        return word.getText();
    }
}
