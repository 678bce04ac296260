package robotworld.explorer.monitor.gui;

import robotworld.core.ServoModule;

/** A servo module: the last position set on each servo, on a 0..180° bar with a needle and in degrees. */
public class ServoModulePanel extends ChannelValuesPanel {

    public ServoModulePanel(String moduleName) {
        super("ServoModule", moduleName, "Servo", ServoModule.SERVOS, 0, 180, 0, true);
    }

    /** Shows servo {@code servo} moved to {@code degrees} by {@code function}. */
    public void showPosition(int servo, int degrees, String function) {
        showValue(servo, degrees + "°", degrees, function);
    }
}
