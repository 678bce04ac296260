package robotworld.explorer.monitor.gui;

import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.util.Arrays;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingConstants;
import robotworld.core.IRDistanceModule;

/**
 * An IR distance module: per sensor a bar as long as the distance it measures (coloured near/middle/far as the
 * world view's rays) and the value in millimetres, or the raw reading when only {@code getAllSensors_ByteRep} was
 * called (thesis figure 4.12, drawn); beside them the rays around the robot, heading up (the body's white wedge
 * points forward, as in the world view), at the sensor angles the monitor assumes
 * ({@link WorldView#ASSUMED_SENSOR_ANGLES}).
 */
public class IRDistanceModulePanel extends ModulePanel {

    private final JLabel[] values = new JLabel[IRDistanceModule.SENSORS];
    private final ValueBar[] bars = new ValueBar[IRDistanceModule.SENSORS];
    private final double[] distances = new double[IRDistanceModule.SENSORS];
    private final RayFan fan = new RayFan();

    public IRDistanceModulePanel(String moduleName) {
        super("IRDistanceModule", moduleName);
        Arrays.fill(distances, Double.NaN);
        JPanel grid = new JPanel(new GridLayout(0, 1, 0, 2));
        for (int i = 0; i < values.length; i++) {
            JPanel row = new JPanel(new BorderLayout(6, 0));
            JLabel label = new JLabel("Sensor " + (i + 1));
            values[i] = new JLabel(ChannelValuesPanel.UNKNOWN, SwingConstants.RIGHT);
            int width = values[i].getFontMetrics(values[i].getFont()).stringWidth("raw 255 mm") + 6;
            values[i].setPreferredSize(new Dimension(width, values[i].getPreferredSize().height));
            values[i].getAccessibleContext().setAccessibleName("sensor " + (i + 1));
            bars[i] = new ValueBar(0, WorldView.ASSUMED_RANGE, 0, false);
            label.setLabelFor(bars[i]);
            row.add(label, BorderLayout.WEST);
            row.add(bars[i], BorderLayout.CENTER);
            row.add(values[i], BorderLayout.EAST);
            grid.add(row);
        }
        JPanel body = new JPanel(new BorderLayout(8, 0));
        body.add(grid, BorderLayout.CENTER);
        body.add(fan, BorderLayout.EAST);
        setBody(body);
    }

    /** Shows the distance of sensor {@code sensor} (1-based) in millimetres. */
    public void showDistance(int sensor, int millimetres) {
        if (show(sensor, millimetres + " mm")) {
            distances[sensor - 1] = millimetres;
            bars[sensor - 1].setValue(millimetres, WorldView.rayColour(millimetres, WorldView.ASSUMED_RANGE));
            fan.repaint();
        }
    }

    /** Shows all distances, sensor 1 first. */
    public void showDistances(int[] millimetres) {
        for (int i = 0; i < millimetres.length; i++) {
            showDistance(i + 1, millimetres[i]);
        }
    }

    /** Shows all raw readings (the module's byte values), sensor 1 first. */
    public void showRawReadings(int[] readings) {
        for (int i = 0; i < readings.length; i++) {
            show(i + 1, "raw " + readings[i]);
        }
    }

    /** The text shown for sensor {@code sensor} (1-based). */
    public String valueText(int sensor) {
        return values[sensor - 1].getText();
    }

    /** The bar of sensor {@code sensor} (1-based). */
    public ValueBar bar(int sensor) {
        return bars[sensor - 1];
    }

    private boolean show(int sensor, String text) {
        if (sensor < 1 || sensor > values.length) {
            showProblem("report about sensor " + sensor + ", which this module does not have");
            return false;
        }
        values[sensor - 1].setText(text);
        return true;
    }

    /** The rays around the robot, heading up. */
    private final class RayFan extends JComponent {
        RayFan() {
            setPreferredSize(new Dimension(120, 120));
            setName("rays");
        }

        @Override
        protected void paintComponent(Graphics graphics) {
            Graphics2D g = (Graphics2D) graphics.create();
            try {
                g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
                double size = Math.min(getWidth(), getHeight());
                double cx = getWidth() / 2.0;
                double cy = getHeight() / 2.0;
                double body = size * 0.14;
                double scale = (size / 2 - body - 2) / WorldView.ASSUMED_RANGE;
                for (int i = 0; i < distances.length; i++) {
                    double angle = Math.toRadians(90 + WorldView.ASSUMED_SENSOR_ANGLES[i]);
                    double dx = Math.cos(angle);
                    double dy = -Math.sin(angle);
                    boolean known = !Double.isNaN(distances[i]);
                    double length = (known ? Math.min(distances[i], WorldView.ASSUMED_RANGE)
                            : WorldView.ASSUMED_RANGE) * scale;
                    g.setColor(known ? WorldView.rayColour(distances[i], WorldView.ASSUMED_RANGE) : WorldView.NO_HIT);
                    g.setStroke(new BasicStroke(known ? 2f : 1f));
                    g.draw(new Line2D.Double(cx + dx * body, cy + dy * body, cx + dx * (body + length),
                            cy + dy * (body + length)));
                }
                WorldView.paintBody(g, new Point2D.Double(cx, cy), body, 90);
            } finally {
                g.dispose();
            }
        }
    }
}
