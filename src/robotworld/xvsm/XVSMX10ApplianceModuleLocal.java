package robotworld.xvsm;

import static robotworld.xvsm.X10Tuples.OFF_CODE;
import static robotworld.xvsm.X10Tuples.ON_CODE;

import java.util.List;
import robotworld.core.X10ApplianceModule;
import robotworld.safety.Actuator;
import robotworld.safety.SafeStates;
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

    private final X10SafeState safeState;
    /** Whether it was last switched on; null before the first command. */
    private volatile Boolean switchedOn;

    /** Serves {@code <participant><moduleName>REQUEST} for {@code hardware} with a thread of its own. */
    public XVSMX10ApplianceModuleLocal(XVSMRuntime runtime, String participant, String moduleName,
                                       X10ApplianceModule hardware) {
        super(runtime, participant, moduleName, hardware);
        safeState = runtime.safety().x10SafeState(participant, moduleName);
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
        switchedOn = on;
        if (on) {
            hardware().on();
        } else {
            hardware().off();
        }
        return List.of();
    }

    @Override
    public String enterSafeState() {
        String done = SafeStates.x10(safeState, hardware()::on, hardware()::off);
        if (safeState != X10SafeState.UNCHANGED) {
            switchedOn = safeState == X10SafeState.ON;
        }
        return done;
    }

    @Override
    public boolean isEngaged() {
        Boolean on = switchedOn;
        return on != null && (safeState == X10SafeState.OFF && on || safeState == X10SafeState.ON && !on);
    }
}
