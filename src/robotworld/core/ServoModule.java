package robotworld.core;

/**
 * A servo control module: up to {@value #SERVOS} hobby servos, numbered 1..{@value #SERVOS}, each positioned at an
 * angle of {@value #MIN_POSITION}..{@value #MAX_POSITION} degrees.
 *
 * <p>Arguments out of range are refused with an {@link IllegalArgumentException} (see {@link ModuleArguments}).
 */
public interface ServoModule {

    /** Number of servo channels. */
    int SERVOS = 8;

    /** Smallest angle in degrees. */
    int MIN_POSITION = 0;

    /** Largest angle in degrees. */
    int MAX_POSITION = 180;

    /**
     * Moves a servo and returns once the module reports that the servo has reached the position. Implementations
     * give up with an unchecked timeout exception when the servo does not get there in time.
     *
     * @param servoNr servo number, 1..{@value #SERVOS}
     * @param position target angle in degrees, 0..180
     */
    void setServo(int servoNr, int position);

    /**
     * Sends the target position and returns at once; the servo moves on its own.
     *
     * @param servoNr servo number, 1..{@value #SERVOS}
     * @param position target angle in degrees, 0..180
     */
    void setServoQuiet(int servoNr, int position);
}
