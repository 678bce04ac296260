package robotworld.explorer.monitor.logic.xvsm;

import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.BumperModulePanel;
import robotworld.observe.WorldTap;
import robotworld.space.Capi;
import robotworld.space.Tuple;
import robotworld.xvsm.CallTuple;

/**
 * Answers {@code <key, mask, getAllBumper>} and {@code <key, <bumperNr, contact>, getSingleBumper>} (thesis
 * table 7, with the bumper number the runtime adds).
 */
public class XVSMBumperModuleMonitor extends XVSMMonitor<BumperModulePanel> {

    public XVSMBumperModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new BumperModulePanel(module.moduleName()));
    }

    /** Watches through a tap shared with the other monitors of the world. */
    public XVSMBumperModuleMonitor(MonitoredModule module, WorldTap tap) {
        super(module, tap, new BumperModulePanel(module.moduleName()));
    }

    @Override
    protected void show(CallTuple answer, BumperModulePanel panel) {
        answer.expectFields(1);
        switch (answer.functionText()) {
            case "getAllBumper" -> panel.showMask(answer.intAt(0));
            case "getSingleBumper" -> {
                Tuple pair = answer.tupleAt(0);
                panel.showContact((int) pair.longAt(0), pair.longAt(1) != 0);
            }
            default -> throw answer.unknownFunction();
        }
    }
}
