package robotworld.xvsm;

import static robotworld.xvsm.X10Tuples.BRIGHTEN;
import static robotworld.xvsm.X10Tuples.DIM;
import static robotworld.xvsm.X10Tuples.NO_LEVEL;
import static robotworld.xvsm.X10Tuples.OFF;
import static robotworld.xvsm.X10Tuples.ON;

import java.util.List;
import robotworld.core.X10LampModule;
import robotworld.safety.Actuator;
import robotworld.safety.SwitchedSafeState;
import robotworld.safety.X10SafeState;
import robotworld.space.Entry;

/**
 * An X10 lamp module driven by this computer's CM11A, shared through the space. Requests and answers:
 * {@code <key, level, "on"|"off"|"brighten"|"dim">}, level 0 for on and off.
 *
 * <p>An actuator whose safe state is configured ({@link X10SafeState}, default: left as it is); it is engaged
 * while it was last switched away from that state (brighten and dim count as on).
 */
public class XVSMX10LampModuleLocal extends XVSMLocalModule<X10LampModule> implements X10LampModule, Actuator {

    private final SwitchedSafeState safety;

    /** Serves {@code <participant><moduleName>REQUEST} for {@code hardware} with a thread of its own. */
    public XVSMX10LampModuleLocal(XVSMRuntime runtime, String participant, String moduleName,
                                  X10LampModule hardware) {
        super(runtime, participant, moduleName, hardware);
        safety = new SwitchedSafeState(runtime.safety().x10SafeState(participant, moduleName));
        start();
    }

    @Override
    public void brighten(int level) {
        callLocally(BRIGHTEN, X10Tuples.level(level));
    }

    @Override
    public void dim(int level) {
        callLocally(DIM, X10Tuples.level(level));
    }

    @Override
    public void on() {
        callLocally(ON, NO_LEVEL);
    }

    @Override
    public void off() {
        callLocally(OFF, NO_LEVEL);
    }

    @Override
    protected List<Entry> perform(CallTuple request) {
        request.expectFields(1);
        int level = request.intAt(0);
        if (request.is(ON) || request.is(OFF) || request.is(BRIGHTEN) || request.is(DIM)) {
            safety.commanded(!request.is(OFF));
        }
        if (request.is(ON)) {
            hardware().on();
        } else if (request.is(OFF)) {
            hardware().off();
        } else if (request.is(BRIGHTEN)) {
            hardware().brighten(level);
        } else if (request.is(DIM)) {
            hardware().dim(level);
        } else {
            throw request.unknownFunction();
        }
        return request.fields();
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
