package robotworld.telemetry;

import java.util.ArrayList;
import java.util.List;
import robotworld.observe.ModuleRef;
import robotworld.observe.WorldLayout;

/** The topic names (see the package documentation). */
public final class Topics {

    /** Participant liveness. */
    public static final Topic LIVENESS = new Topic("/rwe/liveness", "rwe.Liveness");
    /** Actuators that reached their safe state. */
    public static final Topic STOPS = new Topic("/rwe/stops", "rwe.ActuatorStopped");
    /** Events that may be missing. */
    public static final Topic GAPS = new Topic("/rwe/gaps", "rwe.Gap");
    /** Stop records of the safety layer: every actuator put into its safe state, and why. */
    public static final Topic STOP_RECORDS = new Topic("/rwe/stop_records", "rwe.StopRecord");
    /** Heartbeats of the programs (safety layer). */
    public static final Topic HEARTBEATS = new Topic("/rwe/heartbeats", "rwe.Heartbeat");
    /** Where each robot is in the arena, as a transform tree. */
    public static final Topic TRANSFORMS = new Topic("/tf", "foxglove.FrameTransforms");
    /** The frame every robot moves in. */
    public static final String ARENA_FRAME = "arena";

    private Topics() {
    }

    /** A module's requests and answers. */
    public static Topic module(ModuleRef module) {
        return new Topic("/" + module.participant() + "/" + module.name(), "rwe.ModuleTraffic");
    }

    /** A robot's ground truth as the simulator publishes it. */
    public static Topic groundTruth(String robot) {
        return new Topic("/" + robot + "/ground_truth", "rwe.GroundTruth");
    }

    /** A robot's arena, body, bumpers and rays as a 3D scene. */
    public static Topic scene(String robot) {
        return new Topic("/" + robot + "/scene", "foxglove.SceneUpdate");
    }

    /** A robot's pose in the arena. */
    public static Topic pose(String robot) {
        return new Topic("/" + robot + "/pose", "foxglove.PoseInFrame");
    }

    /** One IR sensor's ray as a one-point laser scan. */
    public static Topic ir(String robot, int address, int sensor) {
        return new Topic("/" + robot + "/ir/" + address + "." + sensor, "foxglove.LaserScan");
    }

    /**
     * The topics known before anything happens: every module's, liveness, stops, gaps, stop records, heartbeats,
     * and each robot's ground
     * truth, scene, pose and the transforms. (IR topics appear with the first frame that has rays.)
     */
    public static List<Topic> known(WorldLayout layout) {
        List<Topic> topics = new ArrayList<>();
        for (ModuleRef module : layout.modules()) {
            topics.add(module(module));
        }
        topics.add(LIVENESS);
        topics.add(STOPS);
        topics.add(GAPS);
        topics.add(STOP_RECORDS);
        topics.add(HEARTBEATS);
        List<String> robots = layout.robots().toList();
        for (String robot : robots) {
            topics.add(groundTruth(robot));
            topics.add(scene(robot));
            topics.add(pose(robot));
        }
        if (!robots.isEmpty()) {
            topics.add(TRANSFORMS);
        }
        return topics;
    }
}
