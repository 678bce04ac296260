package robotworld.core;

/**
 * Argument checks shared by every implementation of the module interfaces (hardware proxies, space proxies), so
 * a bad argument is refused the same way everywhere: an {@link IllegalArgumentException} naming the argument, the
 * value and the allowed range.
 */
public final class ModuleArguments {

    private ModuleArguments() {
    }

    /** Checks a motor number, 1..{@value MotorModule#MOTORS}. */
    public static int motorNumber(int motor) {
        return inRange("motor number", motor, 1, MotorModule.MOTORS);
    }

    /** Checks a motor speed, -1.0..1.0 (NaN is refused). */
    public static double speed(double speed) {
        if (!(speed >= MotorModule.MIN_SPEED && speed <= MotorModule.MAX_SPEED)) {
            throw new IllegalArgumentException("speed " + speed + " is outside " + MotorModule.MIN_SPEED + ".."
                    + MotorModule.MAX_SPEED);
        }
        return speed;
    }

    /** Checks a servo number, 1..{@value ServoModule#SERVOS}. */
    public static int servoNumber(int servo) {
        return inRange("servo number", servo, 1, ServoModule.SERVOS);
    }

    /** Checks a servo position, 0..180 degrees. */
    public static int servoPosition(int position) {
        return inRange("servo position", position, ServoModule.MIN_POSITION, ServoModule.MAX_POSITION);
    }

    /** Checks a bumper number, 1..{@value BumperModule#BUMPERS}. */
    public static int bumperNumber(int bumper) {
        return inRange("bumper number", bumper, 1, BumperModule.BUMPERS);
    }

    /** Checks an IR sensor number, 1..{@value IRDistanceModule#SENSORS}. */
    public static int irSensorNumber(int sensor) {
        return inRange("IR sensor number", sensor, 1, IRDistanceModule.SENSORS);
    }

    /** Converts a checked speed to the per-mille value motors use on the bus and in the space (-1000..1000). */
    public static int speedToPerMille(double speed) {
        return (int) Math.round(speed(speed) * 1000);
    }

    private static int inRange(String what, int value, int min, int max) {
        if (value < min || value > max) {
            throw new IllegalArgumentException(what + " " + value + " is outside " + min + ".." + max);
        }
        return value;
    }
}
