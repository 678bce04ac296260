package robotworld.observe;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.Order;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;

/**
 * How {@link GroundTruth} frames travel through the space. A simulator shifts each frame into the container
 * {@code <Robot>GROUNDTRUTH} (LIFO with a KEY view, unbounded: the same spec as a module's ANSWER container) under
 * the key {@value #KEY}, so the container always holds just the newest frame and a monitor started late reads it
 * at once. The space has no floating-point entries, so the frame is integers:
 *
 * <pre>
 * &lt;"rwe.groundtruth", 1, robot, sequence, epochMillis, simulatedMicros,
 *   &lt;width, height, &lt;&lt;x, y, width, height&gt;...&gt;&gt;,               arena and obstacles, mm
 *   &lt;x, y, headingCentidegrees, radius&gt;,                        the body, mm
 *   &lt;&lt;address, sensor, angleCentidegrees, length, range&gt;...&gt;,    IR rays, mm
 *   &lt;&lt;address, number, angleCentidegrees, spanCentidegrees, contact 0|1&gt;...&gt;,  bumpers
 *   &lt;&lt;address, channel, setPerMille, actualPerMille, wheel&gt;...&gt;&gt;   motors; wheel "left", "right" or ""
 * </pre>
 *
 * Lengths are rounded to whole millimetres, angles to hundredths of a degree; motor speeds travel as per-mille,
 * as everywhere on the wire, and are -1..1 in {@link GroundTruth}.
 */
public final class GroundTruthTuples {

    /** The first field of every frame. */
    public static final String TAG = "rwe.groundtruth";
    /** The layout version this class writes and reads. */
    public static final int VERSION = 1;
    /** The key each frame is shifted under. */
    public static final String KEY = "frame";

    private GroundTruthTuples() {
    }

    /** The container of a robot's frames: {@code <Robot>GROUNDTRUTH}. */
    public static String containerName(String robot) {
        return robot + "GROUNDTRUTH";
    }

    /** Its spec: LIFO with a KEY view, unbounded. */
    public static ContainerSpec containerSpec(String robot) {
        return ContainerSpec.of(Order.LIFO).withKeyView().unbounded().named(containerName(robot));
    }

    /** The frame as a tuple. */
    public static Tuple encode(GroundTruth frame) {
        List<Entry> obstacles = new ArrayList<>();
        for (GroundTruth.Obstacle o : frame.arena().obstacles()) {
            obstacles.add(Tuple.of(mm(o.x()), mm(o.y()), mm(o.width()), mm(o.height())));
        }
        List<Entry> rays = new ArrayList<>();
        for (GroundTruth.Ray r : frame.rays()) {
            rays.add(Tuple.of((long) r.address(), (long) r.sensor(), centi(r.angle()), mm(r.length()), mm(r.range())));
        }
        List<Entry> bumpers = new ArrayList<>();
        for (GroundTruth.Bumper b : frame.bumpers()) {
            bumpers.add(Tuple.of((long) b.address(), (long) b.number(), centi(b.angle()), centi(b.span()),
                    b.contact() ? 1L : 0L));
        }
        List<Entry> motors = new ArrayList<>();
        for (GroundTruth.Motor m : frame.motors()) {
            motors.add(Tuple.of((long) m.address(), (long) m.channel(), perMille(m.setPoint()), perMille(m.actual()),
                    m.wheel()));
        }
        GroundTruth.Body body = frame.body();
        return Tuple.of(TAG, (long) VERSION, frame.robot(), frame.sequence(), frame.at().toEpochMilli(),
                Math.round(frame.simulatedSeconds() * 1e6),
                Tuple.of(mm(frame.arena().width()), mm(frame.arena().height()), new Tuple(obstacles)),
                Tuple.of(mm(body.x()), mm(body.y()), centi(body.heading()), mm(body.radius())),
                new Tuple(rays), new Tuple(bumpers), new Tuple(motors));
    }

    /** Whether {@code entry} looks like a frame (its tag), before {@link #decode} checks the rest. */
    public static boolean isFrame(Entry entry) {
        return entry instanceof Tuple tuple && tuple.arity() > 0 && tuple.get(0) instanceof StringEntry tag
                && tag.value().equals(TAG);
    }

    /**
     * Reads a frame.
     *
     * @throws IllegalArgumentException when {@code entry} is not a frame of this version
     */
    public static GroundTruth decode(Entry entry) {
        try {
            Tuple t = (Tuple) entry;
            if (t.arity() != 11 || !t.stringAt(0).equals(TAG)) {
                throw new IllegalArgumentException("not a ground-truth frame: " + entry);
            }
            if (t.longAt(1) != VERSION) {
                throw new IllegalArgumentException("ground-truth layout version " + t.longAt(1) + ", this reader knows "
                        + VERSION);
            }
            Tuple arena = t.tupleAt(6);
            List<GroundTruth.Obstacle> obstacles = new ArrayList<>();
            for (Entry e : arena.tupleAt(2).fields()) {
                Tuple o = (Tuple) e;
                obstacles.add(new GroundTruth.Obstacle(o.longAt(0), o.longAt(1), o.longAt(2), o.longAt(3)));
            }
            Tuple b = t.tupleAt(7);
            List<GroundTruth.Ray> rays = new ArrayList<>();
            for (Entry e : t.tupleAt(8).fields()) {
                Tuple r = (Tuple) e;
                rays.add(new GroundTruth.Ray((int) r.longAt(0), (int) r.longAt(1), r.longAt(2) / 100.0, r.longAt(3),
                        r.longAt(4)));
            }
            List<GroundTruth.Bumper> bumpers = new ArrayList<>();
            for (Entry e : t.tupleAt(9).fields()) {
                Tuple u = (Tuple) e;
                bumpers.add(new GroundTruth.Bumper((int) u.longAt(0), (int) u.longAt(1), u.longAt(2) / 100.0,
                        u.longAt(3) / 100.0, u.longAt(4) != 0));
            }
            List<GroundTruth.Motor> motors = new ArrayList<>();
            for (Entry e : t.tupleAt(10).fields()) {
                Tuple m = (Tuple) e;
                motors.add(new GroundTruth.Motor((int) m.longAt(0), (int) m.longAt(1), m.longAt(2) / 1000.0,
                        m.longAt(3) / 1000.0, m.stringAt(4)));
            }
            return new GroundTruth(t.stringAt(2), t.longAt(3), Instant.ofEpochMilli(t.longAt(4)), t.longAt(5) / 1e6,
                    new GroundTruth.Arena(arena.longAt(0), arena.longAt(1), obstacles),
                    new GroundTruth.Body(b.longAt(0), b.longAt(1), b.longAt(2) / 100.0, b.longAt(3)),
                    rays, bumpers, motors);
        } catch (ClassCastException | IndexOutOfBoundsException e) {
            throw new IllegalArgumentException("not a ground-truth frame (" + e.getMessage() + "): " + entry, e);
        }
    }

    private static IntEntry mm(double millimetres) {
        return new IntEntry(Math.round(millimetres));
    }

    private static IntEntry centi(double degrees) {
        return new IntEntry(Math.round(degrees * 100));
    }

    private static IntEntry perMille(double speed) {
        return new IntEntry(Math.round(speed * 1000));
    }
}
