package robotworld.explorer.monitor.logic.xvsm;

import javax.swing.JTextField;
import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.ModulePanel;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/**
 * Test-only: the monitor of the test-only {@code GripperModule} type. Found by {@code MonitorLoader} through the
 * naming convention alone; nothing in the main sources knows it.
 */
public class XVSMGripperModuleMonitor extends XVSMMonitor<XVSMGripperModuleMonitor.GripperPanel> {

    public XVSMGripperModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new GripperPanel(module.moduleName()));
    }

    @Override
    protected void show(CallTuple answer, GripperPanel panel) {
        panel.force.setText(answer.intAt(0) + " %");
    }

    /** The gripper's force, as last set or read. */
    public static final class GripperPanel extends ModulePanel {

        final JTextField force = new JTextField("–", 6);

        GripperPanel(String moduleName) {
            super("GripperModule", moduleName);
            force.setEditable(false);
            setBody(force);
        }

        public String forceText() {
            return force.getText();
        }
    }
}
