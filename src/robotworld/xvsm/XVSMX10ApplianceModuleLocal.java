package robotworld.xvsm;

import static robotworld.xvsm.X10Tuples.OFF_CODE;
import static robotworld.xvsm.X10Tuples.ON_CODE;

import java.util.List;
import robotworld.core.X10ApplianceModule;
import robotworld.safety.Actuator;
import robotworld.safety.SwitchedSafeState;
import robotworld.safety.X10SafeState;
import robotworld.space.Entry;

/**
 * An X10 appliance module driven by this computer's CM11A, shared through the space. Requests and answers:
 * {@code <key, code>}, code 1 = on, -1 = off (any code below 0 means off).
 *
 * <p>An actuator whose safe state is configured ({@link X10SafeState}, default: left as it is); it is engaged
 * while it was last switched away from that state.
 */
public class XVSMX10ApplianceModuleLocal extends XVSMLocalModule<X10ApplianceModule>
        implements X10ApplianceModule, Actuator {

    private final SwitchedSafeState safety;

    /** Serves {@code <participant><moduleName>REQUEST} for {@code hardware} with a thread of its own. */
    public XVSMX10ApplianceModuleLocal(XVSMRuntime runtime, String participant, String moduleName,
                                       X10ApplianceModule hardware) {
        super(runtime, participant, moduleName, hardware);
        safety = new SwitchedSafeState(runtime.safety().x10SafeState(participant, moduleName));
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
        boolean on = X10Tuples.isOn(request.function());
        safety.commanded(on);
        if (on) {
            hardware().on();
        } else {
            hardware().off();
        }
        return List.of();
    }

    @Override
    public String enterSafeState() {
        return safety.enter(hardware()::on, hardware()::off);
    }

    @Override
    public boolean isEngaged() {
        return safety.isEngaged();
    }
}
