package robotworld.explorer.monitor.gui;

import java.awt.GridLayout;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import robotworld.core.IRDistanceModule;

/**
 * An IR distance module: one field per sensor with the last distance in millimetres, or the raw reading when
 * only {@code getAllSensors_ByteRep} was called (thesis figure 4.12).
 */
public class IRDistanceModulePanel extends ModulePanel {

    private final JTextField[] sensors = new JTextField[IRDistanceModule.SENSORS];

    public IRDistanceModulePanel(String moduleName) {
        super("IRDistanceModule", moduleName);
        JPanel grid = new JPanel(new GridLayout(0, 4, 6, 2));
        for (int i = 0; i < sensors.length; i++) {
            JLabel label = new JLabel("Sensor " + (i + 1));
            sensors[i] = new JTextField(ChannelValuesPanel.UNKNOWN, 7);
            sensors[i].setEditable(false);
            label.setLabelFor(sensors[i]);
            grid.add(label);
            grid.add(sensors[i]);
        }
        setBody(grid);
    }

    /** Shows the distance of sensor {@code sensor} (1-based) in millimetres. */
    public void showDistance(int sensor, int millimetres) {
        show(sensor, millimetres + " mm");
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
        return sensors[sensor - 1].getText();
    }

    private void show(int sensor, String text) {
        if (sensor < 1 || sensor > sensors.length) {
            showProblem("report about sensor " + sensor + ", which this module does not have");
            return;
        }
        sensors[sensor - 1].setText(text);
    }
}
