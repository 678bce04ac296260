package robotworld.sim.robot;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.observe.GroundTruth;
import robotworld.observe.GroundTruthTuples;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.Item;
import robotworld.space.SpaceException;
import robotworld.space.Timeout;

/**
 * Takes a simulated robot's ground truth (arena, pose, IR rays with what they measure, bumper contacts, motor
 * speeds) at a fixed rate, counts bumps, and, when given a space, shifts each frame into
 * {@code <Robot>GROUNDTRUTH} for monitors ({@link GroundTruthTuples}).
 *
 * <p>It never slows the bus: a frame is copied under the simulation's lock in a few microseconds, and the space is
 * talked to afterwards, on this feed's own thread. When the space is slow or away, frames are skipped (the
 * container only ever holds the newest one anyway) and publishing resumes when it answers again; the simulation
 * and its bus go on regardless.
 */
public final class GroundTruthFeed implements AutoCloseable {

    /** 20 frames a second: smooth enough for a live view, cheap for the space. */
    public static final Duration DEFAULT_PERIOD = Duration.ofMillis(50);

    private static final Logger LOG = LoggerFactory.getLogger(GroundTruthFeed.class);
    private static final Timeout SHIFT_TIMEOUT = Timeout.ofMillis(2_000);

    private final Simulation simulation;
    private final String robot;
    private final Capi space;
    private final long periodNanos;
    private final Thread thread;
    private volatile boolean closed;
    private volatile GroundTruth latest;
    private volatile long bumps;
    private volatile long published;
    private volatile String problem;
    private ContainerRef container;
    private long sequence;
    private boolean touching;

    private GroundTruthFeed(Simulation simulation, String robot, Capi space, Duration period) {
        if (!(period.toMillis() >= 1)) {
            throw new IllegalArgumentException("the feed's period must be at least 1 ms, was " + period);
        }
        this.simulation = simulation;
        this.robot = robot;
        this.space = space;
        this.periodNanos = period.toNanos();
        this.latest = snapshot();
        this.thread = new Thread(this::run, "robot-sim-groundtruth " + robot);
        thread.setDaemon(true);
    }

    /**
     * Starts taking frames of {@code robot} every {@code period}.
     *
     * @param participant the robot's name in the world (names the container)
     * @param space       where to publish the frames, or null to only take them (status lines, tests)
     */
    public static GroundTruthFeed start(SimulatedRobot robot, String participant, Capi space, Duration period) {
        GroundTruthFeed feed = new GroundTruthFeed(robot.simulation(), participant, space, period);
        feed.thread.start();
        return feed;
    }

    /** The newest frame. */
    public GroundTruth latest() {
        return latest;
    }

    /** How often the body started touching something since the feed started (seen at the feed's rate). */
    public long bumps() {
        return bumps;
    }

    /** How many frames reached the space. */
    public long published() {
        return published;
    }

    /** Why the last frame did not reach the space, or null when it did (or there is no space). */
    public String problem() {
        return problem;
    }

    /** The container frames go to. */
    public String containerName() {
        return GroundTruthTuples.containerName(robot);
    }

    /** Stops taking frames; waits briefly for a shift under way. Does not close the space. */
    @Override
    public void close() {
        closed = true;
        LockSupport.unpark(thread);
        try {
            thread.join(3_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void run() {
        long next = System.nanoTime();
        while (!closed) {
            GroundTruth frame = snapshot();
            latest = frame;
            if (frame.anyContact() && !touching) {
                bumps++;
            }
            touching = frame.anyContact();
            if (space != null) {
                publish(frame);
            }
            next += periodNanos;
            long now = System.nanoTime();
            if (next - now < 0) {
                next = now; // the space was slow: skip the frames missed, keep the rate from here
            }
            LockSupport.parkNanos(next - now);
        }
    }

    private void publish(GroundTruth frame) {
        try {
            if (container == null) {
                container = space.lookupOrCreateContainer(GroundTruthTuples.containerSpec(robot));
            }
            space.shift(container, SHIFT_TIMEOUT, List.of(Item.keyed(GroundTruthTuples.KEY,
                    GroundTruthTuples.encode(frame))));
            published++;
            if (problem != null) {
                LOG.info("ground truth of {} reaches the space again", robot);
            }
            problem = null;
        } catch (SpaceException e) {
            container = null; // looked up again: the container may be gone with a restarted space
            if (problem == null) {
                LOG.warn("ground truth of {} cannot be published ({}); retrying", robot, e.getMessage());
            }
            problem = e.getMessage() == null ? e.toString() : e.getMessage();
        }
    }

    /** One consistent frame, copied under the simulation's lock. */
    GroundTruth snapshot() {
        long number = ++sequence;
        double seconds = simulation.simulatedSeconds();
        return simulation.inspect(world -> frame(world, number, seconds));
    }

    private GroundTruth frame(World world, long number, double seconds) {
        List<GroundTruth.Obstacle> obstacles = new ArrayList<>();
        for (Rect obstacle : world.obstacles()) {
            obstacles.add(new GroundTruth.Obstacle(obstacle.x(), obstacle.y(), obstacle.width(), obstacle.height()));
        }
        Pose pose = world.pose();
        List<GroundTruth.Ray> rays = new ArrayList<>();
        List<GroundTruth.Bumper> bumpers = new ArrayList<>();
        List<GroundTruth.Motor> motors = new ArrayList<>();
        for (SimModule module : simulation.modules().values()) {
            if (module instanceof SimIRDistanceModule ir) {
                for (Map.Entry<Integer, Double> sensor : ir.angles().entrySet()) {
                    rays.add(new GroundTruth.Ray(ir.address(), sensor.getKey(), sensor.getValue(),
                            ir.distance(sensor.getKey()), ir.range()));
                }
            } else if (module instanceof SimBumperModule bumper) {
                for (Map.Entry<Integer, SimBumperModule.Mount> mount : bumper.mounts().entrySet()) {
                    bumpers.add(new GroundTruth.Bumper(bumper.address(), mount.getKey(), mount.getValue().angle(),
                            mount.getValue().span(), bumper.discreteInput(mount.getKey() - 1)));
                }
            } else if (module instanceof SimMotorModule motor) {
                for (int channel = 1; channel <= SimMotorModule.CHANNELS; channel++) {
                    String wheel = motor.wheelOf(channel);
                    if (!wheel.isEmpty() || motor.setSpeed(channel) != 0 || motor.actualSpeed(channel) != 0) {
                        motors.add(new GroundTruth.Motor(motor.address(), channel, motor.setSpeed(channel) / 1000.0,
                                motor.actualSpeed(channel), wheel));
                    }
                }
            }
        }
        return new GroundTruth(robot, number, Instant.now(), seconds,
                new GroundTruth.Arena(world.width(), world.height(), obstacles),
                new GroundTruth.Body(pose.x(), pose.y(), pose.heading(), world.radius()), rays, bumpers, motors);
    }
}
