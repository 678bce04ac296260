package robotworld.telemetry;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import robotworld.observe.GroundTruth;

/**
 * A ground-truth frame in Foxglove's well-known schemas, so its 3D panel shows the robot move: the transform
 * {@code arena -> <Robot>}, the pose, the scene (arena walls and obstacles; body, heading, bumpers and IR rays)
 * and a one-point laser scan per IR sensor. Metres and radians; the arena's bottom left corner is the origin of
 * frame {@value Topics#ARENA_FRAME}, the robot's frame has x ahead and y to the left.
 */
public final class GroundTruthScene {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;
    private static final double HEIGHT = 0.1;

    private GroundTruthScene() {
    }

    /** {@code foxglove.FrameTransforms}: where the robot's frame is in the arena. */
    public static ObjectNode transforms(GroundTruth frame) {
        ObjectNode node = NODES.objectNode();
        ObjectNode transform = node.putArray("transforms").addObject();
        transform.set("timestamp", time(frame.at()));
        transform.put("parent_frame_id", Topics.ARENA_FRAME);
        transform.put("child_frame_id", frame.robot());
        transform.set("translation", vector(m(frame.body().x()), m(frame.body().y()), 0));
        transform.set("rotation", yaw(Math.toRadians(frame.body().heading())));
        return node;
    }

    /** {@code foxglove.PoseInFrame}: the robot's pose in the arena. */
    public static ObjectNode pose(GroundTruth frame) {
        ObjectNode node = NODES.objectNode();
        node.set("timestamp", time(frame.at()));
        node.put("frame_id", Topics.ARENA_FRAME);
        node.set("pose", pose(m(frame.body().x()), m(frame.body().y()), Math.toRadians(frame.body().heading())));
        return node;
    }

    /** {@code foxglove.LaserScan}: one IR ray as a scan of one point, from the sensor on the body outline. */
    public static ObjectNode scan(GroundTruth frame, GroundTruth.Ray ray) {
        double angle = Math.toRadians(ray.angle());
        double radius = m(frame.body().radius());
        ObjectNode node = NODES.objectNode();
        node.set("timestamp", time(frame.at()));
        node.put("frame_id", frame.robot());
        node.set("pose", pose(radius * Math.cos(angle), radius * Math.sin(angle), angle));
        node.put("start_angle", 0.0);
        node.put("end_angle", 0.0);
        node.putArray("ranges").add(m(ray.length()));
        node.putArray("intensities").add(ray.hits() ? 1.0 : 0.0);
        return node;
    }

    /** {@code foxglove.SceneUpdate}: the arena, and the robot with its bumpers and rays. */
    public static ObjectNode scene(GroundTruth frame) {
        ObjectNode node = NODES.objectNode();
        ArrayNode entities = node.putArray("entities");
        entities.add(arena(frame));
        entities.add(robot(frame));
        return node;
    }

    private static ObjectNode arena(GroundTruth frame) {
        ObjectNode entity = entity(frame, Topics.ARENA_FRAME, frame.robot() + "/arena", false);
        double w = m(frame.arena().width());
        double h = m(frame.arena().height());
        ObjectNode walls = entity.putArray("lines").addObject();
        walls.put("type", 1);
        walls.set("pose", pose(0, 0, 0));
        walls.put("thickness", 0.02);
        walls.put("scale_invariant", false);
        ArrayNode corners = walls.putArray("points");
        corners.add(vector(0, 0, 0)).add(vector(w, 0, 0)).add(vector(w, h, 0)).add(vector(0, h, 0));
        walls.set("color", color(0.3, 0.3, 0.3, 1));
        ArrayNode cubes = entity.putArray("cubes");
        for (GroundTruth.Obstacle o : frame.arena().obstacles()) {
            ObjectNode cube = cubes.addObject();
            cube.set("pose", pose(m(o.x() + o.width() / 2), m(o.y() + o.height() / 2), 0));
            cube.set("size", vector(m(o.width()), m(o.height()), HEIGHT));
            cube.set("color", color(0.55, 0.4, 0.25, 1));
        }
        return entity;
    }

    private static ObjectNode robot(GroundTruth frame) {
        ObjectNode entity = entity(frame, frame.robot(), frame.robot() + "/body", true);
        double radius = m(frame.body().radius());
        ObjectNode body = entity.putArray("cylinders").addObject();
        body.set("pose", pose(0, 0, 0));
        body.set("size", vector(2 * radius, 2 * radius, HEIGHT / 2));
        body.put("bottom_scale", 1.0);
        body.put("top_scale", 1.0);
        body.set("color", frame.anyContact() ? color(0.85, 0.3, 0.3, 0.8) : color(0.3, 0.5, 0.85, 0.8));
        ObjectNode heading = entity.putArray("arrows").addObject();
        heading.set("pose", pose(0, 0, 0));
        heading.put("shaft_length", radius);
        heading.put("shaft_diameter", radius / 8);
        heading.put("head_length", radius / 3);
        heading.put("head_diameter", radius / 4);
        heading.set("color", color(1, 1, 1, 1));
        ArrayNode lines = entity.putArray("lines");
        for (GroundTruth.Bumper bumper : frame.bumpers()) {
            ObjectNode arc = lines.addObject();
            arc.put("type", 0);
            arc.set("pose", pose(0, 0, 0));
            arc.put("thickness", 0.025);
            arc.put("scale_invariant", false);
            ArrayNode points = arc.putArray("points");
            double from = Math.toRadians(bumper.angle() - bumper.span() / 2);
            double to = Math.toRadians(bumper.angle() + bumper.span() / 2);
            for (int i = 0; i <= 12; i++) {
                double a = from + (to - from) * i / 12;
                points.add(vector(radius * 1.05 * Math.cos(a), radius * 1.05 * Math.sin(a), HEIGHT / 2));
            }
            arc.set("color", bumper.contact() ? color(0.9, 0.1, 0.1, 1) : color(0.1, 0.7, 0.2, 1));
        }
        for (GroundTruth.Ray ray : frame.rays()) {
            double a = Math.toRadians(ray.angle());
            double end = radius + m(ray.length());
            ObjectNode line = lines.addObject();
            line.put("type", 0);
            line.set("pose", pose(0, 0, 0));
            line.put("thickness", 0.01);
            line.put("scale_invariant", false);
            line.putArray("points").add(vector(radius * Math.cos(a), radius * Math.sin(a), HEIGHT / 2))
                    .add(vector(end * Math.cos(a), end * Math.sin(a), HEIGHT / 2));
            line.set("color", ray.hits() ? color(0.95, 0.5, 0.1, 1) : color(0.6, 0.6, 0.6, 0.6));
        }
        return entity;
    }

    private static ObjectNode entity(GroundTruth frame, String frameId, String id, boolean locked) {
        ObjectNode entity = NODES.objectNode();
        entity.set("timestamp", time(frame.at()));
        entity.put("frame_id", frameId);
        entity.put("id", id);
        entity.putObject("lifetime").put("sec", 0).put("nsec", 0);
        entity.put("frame_locked", locked);
        entity.putArray("metadata");
        return entity;
    }

    /** A Foxglove time: seconds and nanoseconds since the epoch. */
    public static ObjectNode time(Instant at) {
        return NODES.objectNode().put("sec", at.getEpochSecond()).put("nsec", at.getNano());
    }

    private static ObjectNode pose(double x, double y, double yaw) {
        ObjectNode pose = NODES.objectNode();
        pose.set("position", vector(x, y, 0));
        pose.set("orientation", yaw(yaw));
        return pose;
    }

    private static ObjectNode vector(double x, double y, double z) {
        return NODES.objectNode().put("x", x).put("y", y).put("z", z);
    }

    private static ObjectNode yaw(double radians) {
        return NODES.objectNode().put("x", 0.0).put("y", 0.0).put("z", Math.sin(radians / 2))
                .put("w", Math.cos(radians / 2));
    }

    private static ObjectNode color(double r, double g, double b, double a) {
        return NODES.objectNode().put("r", r).put("g", g).put("b", b).put("a", a);
    }

    private static double m(double millimetres) {
        return millimetres / 1000.0;
    }
}
