package robotworld.explorer.monitor.gui;

import robotworld.core.ServoModule;

/** A servo module: the last position set on each servo, in degrees. */
public class ServoModulePanel extends ChannelValuesPanel {

    public ServoModulePanel(String moduleName) {
        super("ServoModule", moduleName, "Servo", ServoModule.SERVOS);
    }

    /** Shows servo {@code servo} moved to {@code degrees} by {@code function}. */
    public void showPosition(int servo, int degrees, String function) {
        showValue(servo, degrees + "°", function);
    }
}
