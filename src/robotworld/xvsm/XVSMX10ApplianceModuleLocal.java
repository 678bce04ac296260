package robotworld.xvsm;

import static robotworld.xvsm.X10Tuples.OFF_CODE;
import static robotworld.xvsm.X10Tuples.ON_CODE;

import java.util.List;
import robotworld.core.X10ApplianceModule;
import robotworld.space.Entry;

/**
 * An X10 appliance module driven by this computer's CM11A, shared through the space. Requests and answers:
 * {@code <key, code>}, code 1 = on, -1 = off (any code below 0 means off).
 */
public class XVSMX10ApplianceModuleLocal extends XVSMLocalModule<X10ApplianceModule> implements X10ApplianceModule {

    /** Serves {@code <participant><moduleName>REQUEST} for {@code hardware} with a thread of its own. */
    public XVSMX10ApplianceModuleLocal(XVSMRuntime runtime, String participant, String moduleName,
                                       X10ApplianceModule hardware) {
        super(runtime, participant, moduleName, hardware);
        start();
    }

    @Override
    public void on() {
        callLocally(ON_CODE);
    }

    @Override
    public void off() {
        callLocally(OFF_CODE);
    }

    @Override
    protected List<Entry> perform(CallTuple request) {
        request.expectFields(0);
        if (X10Tuples.isOn(request.function())) {
            hardware().on();
        } else {
            hardware().off();
        }
        return List.of();
    }
}
