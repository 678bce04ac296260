package robotworld.explorer.monitor;

import javax.swing.JComponent;
import robotworld.explorer.monitor.gui.PlaceholderPanel;

/** Stands in for a monitor class that is missing or broken: its panel names the class and the reason. */
public final class MissingMonitor implements Monitor {

    private final String className;
    private final String reason;
    private final PlaceholderPanel panel;

    /**
     * @param module    the module that has no working monitor
     * @param className the monitor class that was looked for
     * @param reason    why it is not used
     */
    public MissingMonitor(MonitoredModule module, String className, String reason) {
        this.className = className;
        this.reason = reason;
        this.panel = new PlaceholderPanel(module.moduleClass(), module.moduleName(), className, reason);
    }

    /** The monitor class that was looked for. */
    public String className() {
        return className;
    }

    /** Why it is not used. */
    public String reason() {
        return reason;
    }

    @Override
    public JComponent getPanel() {
        return panel;
    }

    @Override
    public void close() {
        // nothing is watched
    }
}
