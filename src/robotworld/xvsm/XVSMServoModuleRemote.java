package robotworld.xvsm;

import static robotworld.xvsm.ServoTuples.SET_SERVO;
import static robotworld.xvsm.ServoTuples.SET_SERVO_QUIET;

import robotworld.core.ModuleArguments;
import robotworld.core.ServoModule;

/**
 * A servo module of another participant, reached through the space. {@link #setServo} returns once the servo has
 * reached its position at the module's host (keep the call timeout above the servo's move time);
 * {@link #setServoQuiet} returns once the request is in the space.
 */
public class XVSMServoModuleRemote extends XVSMRemoteModule implements ServoModule {

    /** Connects to {@code <participant><moduleName>REQUEST}/{@code ANSWER}. */
    public XVSMServoModuleRemote(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
    }

    @Override
    public void setServo(int servoNr, int position) {
        call(SET_SERVO, ModuleArguments.servoNumber(servoNr), ModuleArguments.servoPosition(position));
    }

    @Override
    public void setServoQuiet(int servoNr, int position) {
        send(SET_SERVO_QUIET, ModuleArguments.servoNumber(servoNr), ModuleArguments.servoPosition(position));
    }
}
