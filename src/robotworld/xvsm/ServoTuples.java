package robotworld.xvsm;

/**
 * Tuples of a servo module (thesis table 6): {@code <key, servoNr, position, function>}, position in degrees
 * 0..180; the answer repeats servo and position.
 */
final class ServoTuples {

    static final String SET_SERVO = "setServo";
    static final String SET_SERVO_QUIET = "setServoQuiet";

    private ServoTuples() {
    }
}
