package robotworld.explorer.monitor.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import javax.swing.JComponent;

/**
 * A horizontal bar for one value between {@code min} and {@code max}, drawn from {@code zero}: a signed bar for
 * motor speeds (-1..1 from 0, forward to the right), a position bar with a needle for servo angles, a length for
 * distances. Grey and empty while the value is unknown. Swing thread only.
 */
public final class ValueBar extends JComponent {

    private static final Color TRACK = new Color(0xE6, 0xE9, 0xED);
    private static final Color EDGE = new Color(0xC4, 0xC9, 0xD0);
    private static final Color POSITIVE = new Color(0x2E, 0xA8, 0x5A);
    private static final Color NEGATIVE = new Color(0xE0, 0x7A, 0x1F);

    private final double min;
    private final double max;
    private final double zero;
    private final boolean needle;
    private double value = Double.NaN;
    private Color colour;

    /**
     * @param zero   where the bar starts (0 for a signed bar, {@code min} for a length)
     * @param needle whether to mark the value with a needle (positions) as well
     */
    public ValueBar(double min, double max, double zero, boolean needle) {
        this.min = min;
        this.max = max;
        this.zero = zero;
        this.needle = needle;
        setPreferredSize(new Dimension(90, 14));
        setMinimumSize(new Dimension(30, 10));
    }

    /** Shows {@code newValue} (NaN: unknown), in the default colours. */
    public void setValue(double newValue) {
        setValue(newValue, null);
    }

    /** Shows {@code newValue} in {@code barColour} (null: green above zero, orange below). */
    public void setValue(double newValue, Color barColour) {
        if (Double.compare(newValue, value) != 0 || barColour != colour) {
            value = newValue;
            colour = barColour;
            repaint();
        }
    }

    /** The value shown, NaN when unknown. */
    public double value() {
        return value;
    }

    private double x(double v, int width) {
        double clamped = Math.max(min, Math.min(max, v));
        return (clamped - min) / (max - min) * (width - 1);
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            int width = getWidth();
            int height = getHeight();
            int top = Math.max(0, (height - 12) / 2);
            int barHeight = Math.min(12, height);
            g.setColor(TRACK);
            g.fillRoundRect(0, top, width - 1, barHeight - 1, 4, 4);
            g.setColor(EDGE);
            g.drawRoundRect(0, top, width - 1, barHeight - 1, 4, 4);
            int zeroX = (int) Math.round(x(zero, width));
            if (zero > min && zero < max) {
                g.drawLine(zeroX, top - 1, zeroX, top + barHeight);
            }
            if (Double.isNaN(value)) {
                return;
            }
            int valueX = (int) Math.round(x(value, width));
            g.setColor(colour != null ? colour : value >= zero ? POSITIVE : NEGATIVE);
            g.fillRect(Math.min(zeroX, valueX), top + 2, Math.max(1, Math.abs(valueX - zeroX)), barHeight - 4);
            if (needle) {
                g.setColor(new Color(0x2B, 0x2F, 0x36));
                g.fillRect(valueX - 1, top - 1, 3, barHeight + 2);
            }
        } finally {
            g.dispose();
        }
    }
}
