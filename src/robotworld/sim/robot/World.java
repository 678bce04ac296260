package robotworld.sim.robot;

import java.util.ArrayList;
import java.util.List;

/**
 * The 2-D world of a simulated robot: a rectangular arena (0,0)..(width,height) in millimetres, axis-aligned
 * obstacles, and one round robot with a differential drive. The robot never overlaps walls or obstacles: a move
 * that would is cut short where the robot touches.
 *
 * <p>Not thread-safe: the {@link Simulation} guards it.
 */
public final class World {

    /** Walls are modelled as thick rectangles around the arena, so they are just obstacles. */
    private static final double WALL = 10_000;

    /** How close the body must be to an obstacle for a bumper to close. */
    static final double CONTACT_TOLERANCE = 1.0;

    private final double width;
    private final double height;
    private final List<Rect> obstacles;
    private final List<Rect> solids = new ArrayList<>();
    private final double radius;
    private final double wheelBase;
    private final double maxSpeed;
    private Pose pose;
    private double travelled;

    /**
     * @param radius body radius in mm
     * @param wheelBase distance between the wheels (tracks) in mm
     * @param maxSpeed wheel speed at motor speed 1.0, in mm/s
     * @throws IllegalArgumentException when the robot does not fit where it starts
     */
    public World(double width, double height, List<Rect> obstacles, Pose start, double radius, double wheelBase,
            double maxSpeed) {
        if (!(width > 0 && height > 0 && radius > 0 && wheelBase > 0 && maxSpeed > 0)) {
            throw new IllegalArgumentException("arena size, radius, wheel base and maximum speed must be positive");
        }
        this.width = width;
        this.height = height;
        this.obstacles = new ArrayList<>(obstacles);
        this.radius = radius;
        this.wheelBase = wheelBase;
        this.maxSpeed = maxSpeed;
        solids.add(new Rect(-WALL, -WALL, WALL, height + 2 * WALL));
        solids.add(new Rect(width, -WALL, WALL, height + 2 * WALL));
        solids.add(new Rect(-WALL, -WALL, width + 2 * WALL, WALL));
        solids.add(new Rect(-WALL, height, width + 2 * WALL, WALL));
        solids.addAll(this.obstacles);
        if (collides(start.x(), start.y())) {
            throw new IllegalArgumentException("the robot (radius " + radius + " mm) does not fit at " + start);
        }
        this.pose = start;
    }

    public Pose pose() {
        return pose;
    }

    public double width() {
        return width;
    }

    public double height() {
        return height;
    }

    public List<Rect> obstacles() {
        return List.copyOf(obstacles);
    }

    /**
     * Puts an obstacle into the arena while the simulation runs (someone pushes a box in the robot's way).
     *
     * @throws IllegalArgumentException when it would overlap the robot
     */
    public void addObstacle(Rect obstacle) {
        solids.add(obstacle);
        if (collides(pose.x(), pose.y())) {
            solids.remove(solids.size() - 1);
            throw new IllegalArgumentException("the obstacle " + obstacle + " would overlap the robot at " + pose);
        }
        obstacles.add(obstacle);
    }

    /** Takes an obstacle out of the arena; false when there is no such obstacle. */
    public boolean removeObstacle(Rect obstacle) {
        boolean removed = obstacles.remove(obstacle);
        if (removed) {
            solids.remove(obstacle);
        }
        return removed;
    }

    public double radius() {
        return radius;
    }

    /** Distance the robot's centre has moved since the start, in mm. */
    public double travelled() {
        return travelled;
    }

    /** Puts the robot somewhere else (tests, resets). */
    public void place(Pose newPose) {
        if (collides(newPose.x(), newPose.y())) {
            throw new IllegalArgumentException("the robot does not fit at " + newPose);
        }
        pose = newPose;
    }

    /**
     * Moves the robot for {@code seconds} with the given wheel speeds (-1..1 of the maximum speed each).
     * Rotation is always possible for a round body; translation stops where the body touches something.
     */
    public void drive(double left, double right, double seconds) {
        double vLeft = left * maxSpeed;
        double vRight = right * maxSpeed;
        double forward = (vLeft + vRight) / 2 * seconds;
        double turn = (vRight - vLeft) / wheelBase * seconds;
        // integrate along the arc's mean heading (second-order accurate for small steps)
        double heading = pose.headingRadians() + turn / 2;
        double dx = forward * Math.cos(heading);
        double dy = forward * Math.sin(heading);
        double fraction = freeFraction(dx, dy);
        double newX = pose.x() + dx * fraction;
        double newY = pose.y() + dy * fraction;
        travelled += Math.hypot(newX - pose.x(), newY - pose.y());
        pose = new Pose(newX, newY, normalize(pose.heading() + Math.toDegrees(turn)));
    }

    /** Whether anything touches the body within the arc [from, to] degrees relative to the heading. */
    public boolean contact(double fromDegrees, double toDegrees) {
        for (Rect solid : solids) {
            double[] c = solid.closestPoint(pose.x(), pose.y());
            double distance = Math.hypot(c[0] - pose.x(), c[1] - pose.y());
            if (distance <= radius + CONTACT_TOLERANCE) {
                double direction = Math.toDegrees(Math.atan2(c[1] - pose.y(), c[0] - pose.x())) - pose.heading();
                if (withinArc(normalize(direction), fromDegrees, toDegrees)) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Distance from the body's outline at {@code angleDegrees} (relative to the heading) to the nearest wall or
     * obstacle straight out in that direction, in mm.
     */
    public double rangeAt(double angleDegrees) {
        double direction = pose.headingRadians() + Math.toRadians(angleDegrees);
        double dx = Math.cos(direction);
        double dy = Math.sin(direction);
        double ox = pose.x() + radius * dx;
        double oy = pose.y() + radius * dy;
        double nearest = Double.POSITIVE_INFINITY;
        for (Rect solid : solids) {
            nearest = Math.min(nearest, solid.rayDistance(ox, oy, dx, dy));
        }
        return nearest;
    }

    private double freeFraction(double dx, double dy) {
        if (dx == 0 && dy == 0) {
            return 0;
        }
        if (!collides(pose.x() + dx, pose.y() + dy)) {
            return 1;
        }
        // bisect for the longest collision-free part of the step
        double free = 0;
        double blocked = 1;
        for (int i = 0; i < 20; i++) {
            double middle = (free + blocked) / 2;
            if (collides(pose.x() + dx * middle, pose.y() + dy * middle)) {
                blocked = middle;
            } else {
                free = middle;
            }
        }
        return free;
    }

    private boolean collides(double x, double y) {
        for (Rect solid : solids) {
            if (solid.distanceTo(x, y) < radius) {
                return true;
            }
        }
        return false;
    }

    private static boolean withinArc(double angle, double from, double to) {
        double start = normalize(from);
        double span = to - from;
        if (span >= 360) {
            return true;
        }
        double offset = angle - start;
        while (offset < 0) {
            offset += 360;
        }
        return offset <= span;
    }

    /** An angle in degrees brought into (-180, 180]. */
    static double normalize(double degrees) {
        double a = degrees % 360;
        if (a <= -180) {
            a += 360;
        } else if (a > 180) {
            a -= 360;
        }
        return a;
    }
}
