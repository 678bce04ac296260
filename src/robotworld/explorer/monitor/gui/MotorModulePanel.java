package robotworld.explorer.monitor.gui;

import java.util.Locale;
import robotworld.core.MotorModule;

/** A motor module: the last speed set on each motor, -1..1 of full speed. */
public class MotorModulePanel extends ChannelValuesPanel {

    public MotorModulePanel(String moduleName) {
        super("MotorModule", moduleName, "Motor", MotorModule.MOTORS);
    }

    /** Shows motor {@code motor} set to {@code perMille} of full speed by {@code function}. */
    public void showSpeed(int motor, int perMille, String function) {
        showValue(motor, String.format(Locale.ROOT, "%+.3f", perMille / 1000.0), function);
    }
}
