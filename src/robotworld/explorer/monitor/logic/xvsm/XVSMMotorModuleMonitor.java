package robotworld.explorer.monitor.logic.xvsm;

import robotworld.core.MotorModule;
import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.MotorModulePanel;
import robotworld.observe.WorldTap;
import robotworld.safety.StopRecord;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/** Answers {@code <key, motorNr, speed per-mille, setMotor|setMotorQuiet>} (as table 6, docs/runtime.md). */
public class XVSMMotorModuleMonitor extends XVSMMonitor<MotorModulePanel> {

    public XVSMMotorModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new MotorModulePanel(module.moduleName()));
    }

    /** Watches through a tap shared with the other monitors of the world. */
    public XVSMMotorModuleMonitor(MonitoredModule module, WorldTap tap) {
        super(module, tap, new MotorModulePanel(module.moduleName()));
    }

    @Override
    protected void show(CallTuple answer, MotorModulePanel panel) {
        answer.expectFields(2);
        panel.showSpeed(answer.intAt(0), answer.intAt(1), answer.functionText());
    }

    /** A stopped motor module has every motor at 0. */
    @Override
    protected void showSafeState(StopRecord record, MotorModulePanel panel) {
        for (int motor = 1; motor <= MotorModule.MOTORS; motor++) {
            panel.showSpeed(motor, 0, record.cause().wireName());
        }
    }
}
