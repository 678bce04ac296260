package robotworld.xvsm;

import static robotworld.xvsm.X10Tuples.OFF_CODE;
import static robotworld.xvsm.X10Tuples.ON_CODE;

import robotworld.core.X10ApplianceModule;
import robotworld.space.Entry;

/** An X10 appliance module of another participant, reached through the space; calls return once the command is sent. */
public class XVSMX10ApplianceModuleRemote extends XVSMRemoteModule implements X10ApplianceModule {

    /** Connects to {@code <participant><moduleName>REQUEST}/{@code ANSWER}. */
    public XVSMX10ApplianceModuleRemote(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
    }

    @Override
    public void on() {
        call(ON_CODE);
    }

    @Override
    public void off() {
        call(OFF_CODE);
    }

    /** Codes read as the interface's names in messages. */
    @Override
    protected String functionName(Entry function) {
        return X10Tuples.isOn(function) ? "on" : "off";
    }
}
