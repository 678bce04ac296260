package robotworld.observe;

import java.time.Instant;
import java.util.List;
import java.util.Objects;

/**
 * Where a simulated robot is and what it senses, as its simulator knows it: one frame. Lengths in millimetres,
 * angles in degrees (headings counter-clockwise from the arena's +x axis; sensor and bumper angles relative to the
 * robot's heading, positive to the left), motor speeds as -1..1 of full speed. The arena's origin is its bottom
 * left corner. How frames travel through the space: {@link GroundTruthTuples}.
 *
 * @param robot            the participant (robot) the frame is about
 * @param sequence         the frame's number, counting from 1 since the simulator started publishing
 * @param at               when the simulator took the frame (its wall clock)
 * @param simulatedSeconds simulated time since the simulator started
 * @param arena            the arena and its obstacles
 * @param body             the robot's pose and size
 * @param rays             one per IR sensor: where it points and what it measures
 * @param bumpers          one per mounted bumper: where it sits and whether it touches something
 * @param motors           one per motor channel: set-point and actual speed
 */
public record GroundTruth(String robot, long sequence, Instant at, double simulatedSeconds, Arena arena, Body body,
                          List<Ray> rays, List<Bumper> bumpers, List<Motor> motors) {

    /** Copies the lists. */
    public GroundTruth {
        Objects.requireNonNull(robot, "robot");
        Objects.requireNonNull(at, "at");
        Objects.requireNonNull(arena, "arena");
        Objects.requireNonNull(body, "body");
        rays = List.copyOf(rays);
        bumpers = List.copyOf(bumpers);
        motors = List.copyOf(motors);
    }

    /** The arena: {@code (0,0)..(width,height)} with axis-aligned obstacles. */
    public record Arena(double width, double height, List<Obstacle> obstacles) {
        /** Copies the list. */
        public Arena {
            obstacles = List.copyOf(obstacles);
        }
    }

    /** An axis-aligned obstacle: left, bottom, width, height. */
    public record Obstacle(double x, double y, double width, double height) {
    }

    /** The robot's centre, heading (degrees) and body radius. */
    public record Body(double x, double y, double heading, double radius) {
    }

    /**
     * An IR sensor's ray, from the body outline outwards.
     *
     * @param address bus address of the IR module
     * @param sensor  sensor number (1..7)
     * @param angle   mounting angle relative to the heading
     * @param length  the distance measured (at most {@code range})
     * @param range   the sensor's range
     */
    public record Ray(int address, int sensor, double angle, double length, double range) {

        /** Whether the ray hits something within the range. */
        public boolean hits() {
            return length < range;
        }
    }

    /**
     * A bumper: an arc of the body outline.
     *
     * @param address bus address of the bumper module
     * @param number  bumper number (1..8)
     * @param angle   centre of the arc relative to the heading
     * @param span    width of the arc
     * @param contact whether something touches the body within the arc
     */
    public record Bumper(int address, int number, double angle, double span, boolean contact) {
    }

    /**
     * A motor channel.
     *
     * @param address  bus address of the motor module
     * @param channel  motor number (1..8)
     * @param setPoint the speed last set, -1..1
     * @param actual   the speed it runs at now (it follows the set-point at a limited rate), -1..1
     * @param wheel    {@code left}, {@code right}, or empty when it drives no wheel
     */
    public record Motor(int address, int channel, double setPoint, double actual, String wheel) {
        /** Checks the wheel. */
        public Motor {
            Objects.requireNonNull(wheel, "wheel");
        }
    }

    /** Whether any bumper touches something. */
    public boolean anyContact() {
        return bumpers.stream().anyMatch(Bumper::contact);
    }
}
