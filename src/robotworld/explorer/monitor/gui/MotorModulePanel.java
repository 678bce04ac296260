package robotworld.explorer.monitor.gui;

import java.util.Locale;
import robotworld.core.MotorModule;

/**
 * A motor module: the last speed set on each motor as a signed bar (forward to the right, green; backward to the
 * left, orange) and as a number, -1..1 of full speed.
 */
public class MotorModulePanel extends ChannelValuesPanel {

    public MotorModulePanel(String moduleName) {
        super("MotorModule", moduleName, "Motor", MotorModule.MOTORS, -1, 1, 0, false);
    }

    /** Shows motor {@code motor} set to {@code perMille} of full speed (as it travels) by {@code function}. */
    public void showSpeed(int motor, int perMille, String function) {
        double speed = perMille / 1000.0;
        showValue(motor, String.format(Locale.ROOT, "%+.3f", speed), speed, function);
    }
}
