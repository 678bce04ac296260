package robotworld.core;

/**
 * A motor control module: up to {@value #MOTORS} DC motor controllers, numbered 1..{@value #MOTORS}, each driven at
 * a speed from {@value #MIN_SPEED} (full reverse) through 0 (stop) to {@value #MAX_SPEED} (full forward).
 *
 * <p>Arguments out of range are refused with an {@link IllegalArgumentException} that names the value and the
 * range (see {@link ModuleArguments}). Hardware failures (no reply, corrupted replies, a refusing module) surface
 * as unchecked exceptions of the implementation.
 */
public interface MotorModule {

    /** Number of motor channels. */
    int MOTORS = 8;

    /** Full reverse. */
    double MIN_SPEED = -1.0;

    /** Full forward. */
    double MAX_SPEED = 1.0;

    /**
     * Sets the speed of a motor and returns once the module has accepted it (the motor may still be ramping).
     *
     * @param motor motor number, 1..{@value #MOTORS}
     * @param speed -1.0..1.0; the module resolves it to per-mille of full speed
     */
    void setMotor(int motor, double speed);

    /**
     * Sends the speed of a motor and returns at once, without waiting for the module's confirmation.
     *
     * @param motor motor number, 1..{@value #MOTORS}
     * @param speed -1.0..1.0
     */
    void setMotorQuiet(int motor, double speed);
}
