package robotworld.xvsm;

import static robotworld.xvsm.ServoTuples.SET_SERVO;
import static robotworld.xvsm.ServoTuples.SET_SERVO_QUIET;

import java.util.List;
import robotworld.core.ModuleArguments;
import robotworld.core.ServoModule;
import robotworld.space.Entry;

/**
 * A servo module attached to this computer, shared through the space. Requests and answers:
 * {@code <key, servoNr, position, "setServo"|"setServoQuiet">}.
 */
public class XVSMServoModuleLocal extends XVSMLocalModule<ServoModule> implements ServoModule {

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
}
