package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GridLayout;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingConstants;

/**
 * One row per channel (servo or motor number) with a bar and the last value set on it; the tooltip names the
 * function that set it (thesis figure 4.10, drawn). Channels are numbered from 1.
 */
public abstract class ChannelValuesPanel extends ModulePanel {

    /** Text of a channel nobody has set since monitoring started. */
    public static final String UNKNOWN = "–";

    private final JLabel[] values;
    private final ValueBar[] bars;

    /**
     * @param min, max the values the bars span
     * @param zero     where a bar starts
     * @param needle   whether the bars mark the value with a needle
     */
    protected ChannelValuesPanel(String moduleClass, String moduleName, String channelWord, int channels, double min,
            double max, double zero, boolean needle) {
        super(moduleClass, moduleName);
        values = new JLabel[channels];
        bars = new ValueBar[channels];
        JPanel grid = new JPanel(new GridLayout(0, 2, 12, 3));
        for (int i = 0; i < channels; i++) {
            JPanel row = new JPanel(new BorderLayout(6, 0));
            JLabel label = new JLabel(channelWord + " " + (i + 1));
            values[i] = new JLabel(UNKNOWN, SwingConstants.RIGHT);
            int width = values[i].getFontMetrics(values[i].getFont()).stringWidth("+0.000") + 14;
            values[i].setPreferredSize(new Dimension(width, values[i].getPreferredSize().height));
            values[i].setBorder(BorderFactory.createEmptyBorder(0, 0, 0, 2));
            values[i].getAccessibleContext().setAccessibleName(channelWord + " " + (i + 1));
            bars[i] = new ValueBar(min, max, zero, needle);
            label.setLabelFor(bars[i]);
            row.add(label, BorderLayout.WEST);
            row.add(bars[i], BorderLayout.CENTER);
            row.add(values[i], BorderLayout.EAST);
            grid.add(row);
        }
        setBody(grid);
    }

    /**
     * Shows {@code value} (text) and {@code number} (bar) on channel {@code channel} (1-based), set by
     * {@code function}; reports unknown channels as a problem.
     */
    protected void showValue(int channel, String value, double number, String function) {
        if (channel < 1 || channel > values.length) {
            showProblem("report about channel " + channel + ", which this module does not have");
            return;
        }
        values[channel - 1].setText(value);
        values[channel - 1].setToolTipText("set by " + function);
        bars[channel - 1].setValue(number);
    }

    /** The text shown for channel {@code channel} (1-based). */
    public String valueText(int channel) {
        return values[channel - 1].getText();
    }

    /** The bar of channel {@code channel} (1-based). */
    public ValueBar bar(int channel) {
        return bars[channel - 1];
    }

    /** How many channels are shown. */
    public int channels() {
        return values.length;
    }
}
