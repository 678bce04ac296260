package robotworld.explorer.monitor.logic.xvsm;

import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.MotorModulePanel;
import robotworld.core.MotorModule;
import robotworld.safety.StopRecord;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/** Answers {@code <key, motorNr, speed per-mille, setMotor|setMotorQuiet>} (as table 6, docs/runtime.md). */
public class XVSMMotorModuleMonitor extends XVSMMonitor<MotorModulePanel> {

    public XVSMMotorModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new MotorModulePanel(module.moduleName()));
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
