package robotworld.explorer.monitor.logic.xvsm;

import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.X10ApplianceModulePanel;
import robotworld.observe.WorldTap;
import robotworld.space.Capi;
import robotworld.space.IntEntry;
import robotworld.xvsm.CallTuple;
import robotworld.xvsm.MalformedCallException;

/** Answers {@code <key, code>}: code below 0 off, else on (thesis table 4). */
public class XVSMX10ApplianceModuleMonitor extends XVSMMonitor<X10ApplianceModulePanel> {

    public XVSMX10ApplianceModuleMonitor(MonitoredModule module, Capi space) {
        super(module, space, new X10ApplianceModulePanel(module.moduleName()));
    }

    /** Watches through a tap shared with the other monitors of the world. */
    public XVSMX10ApplianceModuleMonitor(MonitoredModule module, WorldTap tap) {
        super(module, tap, new X10ApplianceModulePanel(module.moduleName()));
    }

    @Override
    protected void show(CallTuple answer, X10ApplianceModulePanel panel) {
        if (!(answer.function() instanceof IntEntry code)) {
            throw new MalformedCallException("an appliance function code is an integer");
        }
        panel.showOn(code.value() >= 0);
    }
}
