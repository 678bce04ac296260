package robotworld.xvsm;

/**
 * Tuples of a motor module, as a servo module's (thesis table 6): {@code <key, motorNr, speed, function>} with the
 * speed in integer per-mille of full speed (-1000..1000); the answer repeats motor and speed, which is what a
 * monitor shows.
 */
final class MotorTuples {

    static final String SET_MOTOR = "setMotor";
    static final String SET_MOTOR_QUIET = "setMotorQuiet";

    private MotorTuples() {
    }

    /** Per-mille of full speed back to the interface's -1..1. */
    static double speed(int perMille) {
        return perMille / 1000.0;
    }
}
