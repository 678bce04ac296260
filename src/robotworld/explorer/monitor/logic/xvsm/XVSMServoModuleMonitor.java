package robotworld.explorer.monitor.logic.xvsm;

import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.ServoModulePanel;
import robotworld.observe.WorldTap;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/** Answers {@code <key, servoNr, position, setServo|setServoQuiet>} (thesis table 6). */
public class XVSMServoModuleMonitor extends XVSMMonitor<ServoModulePanel> {

    public XVSMServoModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new ServoModulePanel(module.moduleName()));
    }

    /** Watches through a tap shared with the other monitors of the world. */
    public XVSMServoModuleMonitor(MonitoredModule module, WorldTap tap) {
        super(module, tap, new ServoModulePanel(module.moduleName()));
    }

    @Override
    protected void show(CallTuple answer, ServoModulePanel panel) {
        answer.expectFields(2);
        panel.showPosition(answer.intAt(0), answer.intAt(1), answer.functionText());
    }
}
