package robotworld.xvsm;

import static robotworld.xvsm.MotorTuples.SET_MOTOR;
import static robotworld.xvsm.MotorTuples.SET_MOTOR_QUIET;

import robotworld.core.ModuleArguments;
import robotworld.core.MotorModule;

/**
 * A motor module of another participant, reached through the space. {@link #setMotor} returns once the module's
 * host has set the speed; {@link #setMotorQuiet} returns once the request is in the space, without waiting for an
 * answer.
 */
public class XVSMMotorModuleRemote extends XVSMRemoteModule implements MotorModule {

    /** Connects to {@code <participant><moduleName>REQUEST}/{@code ANSWER}. */
    public XVSMMotorModuleRemote(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
    }

    @Override
    public void setMotor(int motor, double speed) {
        call(SET_MOTOR, ModuleArguments.motorNumber(motor), ModuleArguments.speedToPerMille(speed));
    }

    @Override
    public void setMotorQuiet(int motor, double speed) {
        send(SET_MOTOR_QUIET, ModuleArguments.motorNumber(motor), ModuleArguments.speedToPerMille(speed));
    }
}
