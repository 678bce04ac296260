package robotworld.explorer.monitor;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import robotworld.core.BumperModule;
import robotworld.core.IRDistanceModule;
import robotworld.core.MotorModule;
import robotworld.observe.AnswerSeen;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldObserver;

/**
 * What each robot's modules last reported, for the robot-frame view when no simulator publishes ground truth (real
 * hardware): IR distances, bumper contacts, motor set-points. Where several modules of a type exist, the last one
 * to report wins. Fed by a {@link robotworld.observe.WorldTap}; read from any thread.
 */
public final class RobotReadings implements WorldObserver {

    /**
     * One robot's last readings; NaN (distances, speeds) or null (contacts) where nothing was reported.
     *
     * @param robot     the robot's name
     * @param distances IR distances in mm, sensor 1 first
     * @param contacts  bumper contacts, bumper 1 first
     * @param speeds    motor set-points -1..1, motor 1 first
     * @param reports   how many answers went into it
     */
    public record Snapshot(String robot, double[] distances, Boolean[] contacts, double[] speeds, long reports) {

        /** Whether any reading came in. */
        public boolean hasReadings() {
            return reports > 0;
        }
    }

    private final Map<String, Readings> robots = new LinkedHashMap<>();

    /** Readings of the robots of {@code layout}. */
    public RobotReadings(WorldLayout layout) {
        layout.robots().forEach(robot -> robots.put(robot, new Readings()));
    }

    /** The last readings of {@code robot}, or null when it is not a robot of the layout. */
    public synchronized Snapshot of(String robot) {
        Readings r = robots.get(robot);
        return r == null ? null : new Snapshot(robot, r.distances.clone(), r.contacts.clone(), r.speeds.clone(),
                r.reports);
    }

    /** The robots' names, in layout order. */
    public synchronized java.util.List<String> robots() {
        return java.util.List.copyOf(robots.keySet());
    }

    @Override
    public synchronized void answerSeen(AnswerSeen event) {
        Readings readings = robots.get(event.module().participant());
        if (readings == null) {
            return;
        }
        String type = event.module().moduleClass();
        boolean used = false;
        for (NumericChannels.Sample sample : NumericChannels.of(type, event.answer(), null)) {
            int index = sample.number() - 1;
            switch (type) {
                case "IRDistanceModule" -> used |= set(readings.distances, index, sample.value());
                case "MotorModule" -> used |= set(readings.speeds, index, sample.value());
                case "BumperModule" -> {
                    if (index >= 0 && index < readings.contacts.length) {
                        readings.contacts[index] = sample.value() != 0;
                        used = true;
                    }
                }
                default -> {
                    // servos and X10 modules are not drawn in the robot's frame
                }
            }
        }
        if (used) {
            readings.reports++;
        }
    }

    private static boolean set(double[] values, int index, double value) {
        if (index < 0 || index >= values.length) {
            return false;
        }
        values[index] = value;
        return true;
    }

    private static final class Readings {
        final double[] distances = nan(IRDistanceModule.SENSORS);
        final Boolean[] contacts = new Boolean[BumperModule.BUMPERS];
        final double[] speeds = nan(MotorModule.MOTORS);
        long reports;

        private static double[] nan(int size) {
            double[] values = new double[size];
            Arrays.fill(values, Double.NaN);
            return values;
        }
    }
}
