package robotworld.xvsm;

import static robotworld.xvsm.ServoTuples.SET_SERVO;
import static robotworld.xvsm.ServoTuples.SET_SERVO_QUIET;

import java.util.List;
import robotworld.core.ModuleArguments;
import robotworld.core.ServoModule;
import robotworld.safety.Actuator;
import robotworld.safety.SafeStates;
import robotworld.space.Entry;

/**
 * A servo module attached to this computer, shared through the space. Requests and answers:
 * {@code <key, servoNr, position, "setServo"|"setServoQuiet">}.
 *
 * <p>An actuator whose safe state is to hold: stopping sends nothing, so every servo keeps its target (it is never
 * made limp, which could drop what it holds). It is never engaged, so losing its commander changes nothing; a stop
 * still makes its commanders' next calls be refused, so they learn of it.
 */
public class XVSMServoModuleLocal extends XVSMLocalModule<ServoModule> implements ServoModule, Actuator {

    /** Serves {@code <participant><moduleName>REQUEST} for {@code hardware} with a thread of its own. */
    public XVSMServoModuleLocal(XVSMRuntime runtime, String participant, String moduleName, ServoModule hardware) {
        super(runtime, participant, moduleName, hardware);
        start();
    }

    @Override
    public void setServo(int servoNr, int position) {
        callLocally(SET_SERVO, ModuleArguments.servoNumber(servoNr), ModuleArguments.servoPosition(position));
    }

    @Override
    public void setServoQuiet(int servoNr, int position) {
        callLocally(SET_SERVO_QUIET, ModuleArguments.servoNumber(servoNr), ModuleArguments.servoPosition(position));
    }

    @Override
    protected List<Entry> perform(CallTuple request) {
        request.expectFields(2);
        int servo = request.intAt(0);
        int position = request.intAt(1);
        if (request.is(SET_SERVO)) {
            hardware().setServo(servo, position);
        } else if (request.is(SET_SERVO_QUIET)) {
            hardware().setServoQuiet(servo, position);
        } else {
            throw request.unknownFunction();
        }
        return request.fields();
    }

    @Override
    public String enterSafeState() {
        return SafeStates.SERVOS_HOLD;
    }

    @Override
    public boolean isEngaged() {
        return false;
    }
}
