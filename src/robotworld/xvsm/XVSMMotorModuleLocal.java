package robotworld.xvsm;

import static robotworld.xvsm.MotorTuples.SET_MOTOR;
import static robotworld.xvsm.MotorTuples.SET_MOTOR_QUIET;

import java.util.List;
import java.util.concurrent.atomic.AtomicIntegerArray;
import robotworld.core.ModuleArguments;
import robotworld.core.MotorModule;
import robotworld.safety.Actuator;
import robotworld.safety.SafeStates;
import robotworld.safety.SafetySettings;
import robotworld.space.Entry;

/**
 * A motor module attached to this computer, shared through the space. Requests and answers:
 * {@code <key, motorNr, speedPerMille, "setMotor"|"setMotorQuiet">}.
 *
 * <p>An actuator: its safe state is every motor at 0 ({@link SafeStates#stopMotors}); it is engaged while any motor
 * was last commanded to a speed other than 0. A motor module on the bus has its communication watchdog armed
 * (500 ms unless configured: {@link SafetySettings}), so it stops by itself if this program dies.
 */
public class XVSMMotorModuleLocal extends XVSMLocalModule<MotorModule> implements MotorModule, Actuator {

    /** The speed each motor was last commanded to, in per-mille (whether or not the hardware confirmed it). */
    private final AtomicIntegerArray commanded = new AtomicIntegerArray(MOTORS);

    /** Serves {@code <participant><moduleName>REQUEST} for {@code hardware} with a thread of its own. */
    public XVSMMotorModuleLocal(XVSMRuntime runtime, String participant, String moduleName, MotorModule hardware) {
        super(runtime, participant, moduleName, hardware);
        start();
    }

    @Override
    public void setMotor(int motor, double speed) {
        callLocally(SET_MOTOR, ModuleArguments.motorNumber(motor), ModuleArguments.speedToPerMille(speed));
    }

    @Override
    public void setMotorQuiet(int motor, double speed) {
        callLocally(SET_MOTOR_QUIET, ModuleArguments.motorNumber(motor), ModuleArguments.speedToPerMille(speed));
    }

    @Override
    protected List<Entry> perform(CallTuple request) {
        request.expectFields(2);
        int motor = request.intAt(0);
        double speed = MotorTuples.speed(request.intAt(1));
        if (request.is(SET_MOTOR) || request.is(SET_MOTOR_QUIET)) {
            ModuleArguments.motorNumber(motor);
            ModuleArguments.speedToPerMille(speed);
            commanded.set(motor - 1, request.intAt(1));
        }
        if (request.is(SET_MOTOR)) {
            hardware().setMotor(motor, speed);
        } else if (request.is(SET_MOTOR_QUIET)) {
            hardware().setMotorQuiet(motor, speed);
        } else {
            throw request.unknownFunction();
        }
        return request.fields();
    }

    /** Motor modules on the bus get a watchdog unless configured otherwise: they are what drives on. */
    @Override
    protected int defaultWatchdogMillis() {
        return SafetySettings.DEFAULT_MOTOR_WATCHDOG_MILLIS;
    }

    @Override
    public String enterSafeState() {
        String done = SafeStates.stopMotors(hardware());
        for (int i = 0; i < MOTORS; i++) {
            commanded.set(i, 0);
        }
        return done;
    }

    @Override
    public boolean isEngaged() {
        for (int i = 0; i < MOTORS; i++) {
            if (commanded.get(i) != 0) {
                return true;
            }
        }
        return false;
    }
}
