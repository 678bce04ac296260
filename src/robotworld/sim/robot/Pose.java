package robotworld.sim.robot;

/**
 * Where the robot is: centre in millimetres and heading in degrees (0 = along +x, counter-clockwise positive).
 */
public record Pose(double x, double y, double heading) {

    /** The heading in radians. */
    public double headingRadians() {
        return Math.toRadians(heading);
    }

    /** Distance between the centres of two poses. */
    public double distanceTo(Pose other) {
        return Math.hypot(other.x - x, other.y - y);
    }

    @Override
    public String toString() {
        return String.format("(%.1f, %.1f) heading %.1f", x, y, heading);
    }
}
