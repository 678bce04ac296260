package robotworld.explorer.monitor.logic.xvsm;

import robotworld.explorer.monitor.LampLevel;
import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.X10LampModulePanel;
import robotworld.observe.WorldTap;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/**
 * Answers {@code <key, level, on|off|brighten|dim>} (thesis table 5). The level in a dim or brighten is a change,
 * so the brightness shown is summed up by {@link LampLevel}.
 */
public class XVSMX10LampModuleMonitor extends XVSMMonitor<X10LampModulePanel> {

    private final LampLevel lamp = new LampLevel();

    public XVSMX10LampModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new X10LampModulePanel(module.moduleName()));
    }

    /** Watches through a tap shared with the other monitors of the world. */
    public XVSMX10LampModuleMonitor(MonitoredModule module, WorldTap tap) {
        super(module, tap, new X10LampModulePanel(module.moduleName()));
    }

    @Override
    protected void show(CallTuple answer, X10LampModulePanel panel) {
        int change = answer.expectFields(1).intAt(0);
        switch (answer.functionText()) {
            case "on" -> lamp.on();
            case "off" -> lamp.off();
            case "brighten" -> lamp.brighten(change);
            case "dim" -> lamp.dim(change);
            default -> throw answer.unknownFunction();
        }
        panel.showLamp(lamp.isOn(), lamp.level());
    }
}
