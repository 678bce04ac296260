package robotworld.explorer.monitor.gui;

import javax.swing.LookAndFeel;
import javax.swing.UIManager;
import com.formdev.flatlaf.FlatLightLaf;

/** The monitor's look: FlatLaf's light theme, installed once before the first monitor window is built. */
public final class MonitorLook {

    private MonitorLook() {
    }

    /**
     * Installs FlatLaf unless another non-default look and feel was chosen already (e.g. with
     * {@code -Dswing.defaultlaf}). Swing thread. Windows built before keep their look.
     */
    public static void install() {
        LookAndFeel current = UIManager.getLookAndFeel();
        if (current instanceof FlatLightLaf) {
            return;
        }
        if (current != null && !current.getClass().getName().equals("javax.swing.plaf.metal.MetalLookAndFeel")) {
            return;
        }
        FlatLightLaf.setup();
    }
}
