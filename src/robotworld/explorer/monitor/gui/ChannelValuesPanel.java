package robotworld.explorer.monitor.gui;

import java.awt.GridLayout;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * One read-only field per channel (servo or motor number) with the last value set on it and the function that
 * set it (thesis figure 4.10). Channels are numbered from 1.
 */
public abstract class ChannelValuesPanel extends ModulePanel {

    /** Text of a channel nobody has set since monitoring started. */
    public static final String UNKNOWN = "–";

    private final JTextField[] values;

    protected ChannelValuesPanel(String moduleClass, String moduleName, String channelWord, int channels) {
        super(moduleClass, moduleName);
        values = new JTextField[channels];
        JPanel grid = new JPanel(new GridLayout(0, 4, 6, 2));
        for (int i = 0; i < channels; i++) {
            JLabel label = new JLabel(channelWord + " " + (i + 1));
            values[i] = new JTextField(UNKNOWN, 8);
            values[i].setEditable(false);
            label.setLabelFor(values[i]);
            grid.add(label);
            grid.add(values[i]);
        }
        setBody(grid);
    }

    /** Shows {@code value} on channel {@code channel} (1-based), set by {@code function}; ignores unknown channels. */
    protected void showValue(int channel, String value, String function) {
        if (channel < 1 || channel > values.length) {
            showProblem("report about channel " + channel + ", which this module does not have");
            return;
        }
        values[channel - 1].setText(value);
        values[channel - 1].setToolTipText("set by " + function);
    }

    /** The text shown for channel {@code channel} (1-based). */
    public String valueText(int channel) {
        return values[channel - 1].getText();
    }

    /** How many channels are shown. */
    public int channels() {
        return values.length;
    }
}
