package robotworld.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import robotworld.observe.WorldTap;
import robotworld.recording.SimWorld;
import robotworld.sim.robot.Pose;
import robotworld.sim.robot.SimIRDistanceModule;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/** The endpoint against the reference Foxglove client, over a running simulated world. */
class FoxgloveBridgeTest {

    @Test
    void theReferenceClientGetsTheChannelsAndTheLiveMessagesInOrder() throws Exception {
        try (SimWorld world = SimWorld.start();
             FoxgloveBridge bridge = FoxgloveBridge.start(SimWorld.LAYOUT, FoxgloveBridge.Options.defaults()
                     .port(0))) {
            WorldTap tap = new WorldTap(world.space(), SimWorld.LAYOUT).add(bridge.observer()).start();
            try (FoxglovePeer client = FoxglovePeer.connect(bridge.uri(), "/SimBot/Motor", "/SimBot/ground_truth",
                    "/tf", "/SimBot/scene", "/rwe/liveness")) {
                JsonNode info = client.await(e -> e.path("event").asText().equals("serverInfo"), "serverInfo");
                assertTrue(info.get("name").asText().contains("SimWorld"), info.toString());
                JsonNode advertise = client.await(e -> e.path("event").asText().equals("advertise"), "advertise");
                Set<String> topics = topics(advertise);
                assertTrue(topics.containsAll(List.of("/SimBot/Motor", "/SimBot/Bumper", "/SimBot/IR",
                        "/rwe/liveness", "/rwe/stops", "/rwe/gaps", "/SimBot/ground_truth", "/SimBot/scene",
                        "/SimBot/pose", "/tf")), topics.toString());
                for (JsonNode channel : advertise.get("channels")) {
                    assertEquals("json", channel.get("encoding").asText());
                    assertEquals("jsonschema", channel.get("schemaEncoding").asText());
                    assertTrue(channel.get("schemaLength").asInt() > 50, channel.toString());
                }
                awaitSubscriptions(bridge, 5);

                XVSMRuntime laptop = world.host("laptop");
                XVSMMotorModuleRemote motor = new XVSMMotorModuleRemote(laptop, SimWorld.ROBOT, "Motor");
                for (int i = 1; i <= 30; i++) {
                    motor.setMotor(1, i / 100.0);
                }
                motor.setMotor(1, 0);
                client.await(e -> e.path("topic").asText().equals("/SimBot/Motor")
                        && e.at("/data/kind").asText().equals("answer") && e.at("/data/fields/1").asInt() == 0,
                        "the last motor answer");
                client.await(e -> e.path("topic").asText().equals("/rwe/liveness")
                        && e.at("/data/state").asText().equals("ALIVE"), "the robot alive");

                List<JsonNode> motorAnswers = client.events("message").stream()
                        .filter(e -> e.get("topic").asText().equals("/SimBot/Motor")
                                && e.at("/data/kind").asText().equals("answer")).toList();
                List<Integer> speeds = motorAnswers.stream().map(e -> e.at("/data/fields/1").asInt()).toList();
                List<Integer> expected = new java.util.ArrayList<>();
                for (int i = 1; i <= 30; i++) {
                    expected.add(i * 10);
                }
                expected.add(0);
                assertEquals(expected, speeds.subList(speeds.size() - 31, speeds.size()), "in order, none lost");
                assertEquals(31, client.events("message").stream().filter(e -> e.get("topic").asText()
                        .equals("/SimBot/Motor") && e.at("/data/kind").asText().equals("request")).count());

                List<JsonNode> frames = client.events("message").stream()
                        .filter(e -> e.get("topic").asText().equals("/SimBot/ground_truth")).toList();
                assertTrue(frames.size() >= 3, "frames: " + frames.size());
                long previous = -1;
                for (JsonNode frame : frames) {
                    long sequence = frame.at("/data/sequence").asLong();
                    assertTrue(sequence > previous, "frames in order: " + sequence + " after " + previous);
                    previous = sequence;
                    assertEquals("rwe.GroundTruth", frame.get("schemaName").asText());
                }
                JsonNode transform = client.await(e -> e.path("topic").asText().equals("/tf"), "a transform");
                assertEquals("arena", transform.at("/data/transforms/0/parent_frame_id").asText());
                assertEquals("SimBot", transform.at("/data/transforms/0/child_frame_id").asText());
                JsonNode scene = client.await(e -> e.path("topic").asText().equals("/SimBot/scene"), "a scene");
                assertEquals("foxglove.SceneUpdate", scene.get("schemaName").asText());
                assertEquals(1, scene.at("/data/entities/0/cubes").size(), "the obstacle");
            } finally {
                tap.close();
            }
        }
    }

    @Test
    void theReferenceClientGetsTheSimulatedRobotsPoseAndIrRaysAsTheSimulatorHasThem() throws Exception {
        List<String> ir = List.of("/SimBot/ir/4.1", "/SimBot/ir/4.2", "/SimBot/ir/4.3");
        List<String> subscribed = new java.util.ArrayList<>(List.of("/SimBot/pose"));
        subscribed.addAll(ir);
        try (SimWorld world = SimWorld.start();
             FoxgloveBridge bridge = FoxgloveBridge.start(SimWorld.LAYOUT, FoxgloveBridge.Options.defaults()
                     .port(0))) {
            WorldTap tap = new WorldTap(world.space(), SimWorld.LAYOUT).add(bridge.observer()).start();
            try (FoxglovePeer client = FoxglovePeer.connect(bridge.uri(), subscribed.toArray(String[]::new))) {
                // the IR channels are advertised with the first frame that has rays: one per sensor
                awaitSubscriptions(bridge, subscribed.size());
                Set<String> advertised = client.events("advertise").stream().flatMap(a -> topics(a).stream())
                        .collect(Collectors.toSet());
                assertEquals(Set.copyOf(ir), advertised.stream().filter(t -> t.startsWith("/SimBot/ir/"))
                        .collect(Collectors.toSet()), "one LaserScan channel per IR sensor of the robot");

                // the robot turns on its left wheel, then stops: its pose is no longer the one it started in
                XVSMMotorModuleRemote motor = new XVSMMotorModuleRemote(world.host("laptop"), SimWorld.ROBOT,
                        "Motor");
                motor.setMotor(1, 0.5);
                Thread.sleep(500);
                motor.setMotor(1, 0);
                Pose still = standingStill(world);
                long stillSince = System.currentTimeMillis() * 1_000_000L;
                assertTrue(Math.abs(angleBetween(still.heading(), 0)) > 5, "the robot turned: " + still);

                JsonNode pose = client.await(e -> e.path("topic").asText().equals("/SimBot/pose")
                        && receiveTime(e) >= stillSince, "a pose taken after the robot stopped");
                assertEquals("foxglove.PoseInFrame", pose.get("schemaName").asText());
                assertEquals("arena", pose.at("/data/frame_id").asText());
                // frames travel through the space in whole millimetres and hundredths of a degree
                assertEquals(still.x() / 1000, pose.at("/data/pose/position/x").asDouble(), 0.001, pose.toString());
                assertEquals(still.y() / 1000, pose.at("/data/pose/position/y").asDouble(), 0.001, pose.toString());
                assertEquals(0, angleBetween(still.heading(), yaw(pose.at("/data/pose/orientation"))), 0.5,
                        pose.toString());

                SimIRDistanceModule sensors = (SimIRDistanceModule) world.robot().module(4);
                double[] mounted = {0, 90, -90}; // SimWorld's sensors 1..3
                for (int sensor = 1; sensor <= 3; sensor++) {
                    String topic = ir.get(sensor - 1);
                    JsonNode scan = client.await(e -> e.path("topic").asText().equals(topic)
                            && receiveTime(e) >= stillSince, "a scan of " + topic + " after the robot stopped");
                    assertEquals("foxglove.LaserScan", scan.get("schemaName").asText());
                    assertEquals("SimBot", scan.at("/data/frame_id").asText(), "in the robot's frame");
                    assertEquals(1, scan.at("/data/ranges").size(), "one ray per sensor: " + scan);
                    double range = scan.at("/data/ranges/0").asDouble();
                    assertTrue(range >= 0 && range <= 0.8, "within the sensor's 800 mm: " + scan);
                    int seen = sensor;
                    int simulated = world.robot().simulation().inspect(w -> sensors.distance(seen));
                    assertEquals(simulated / 1000.0, range, 0.0005, topic + " as the simulator measures it");
                    assertEquals(0, angleBetween(mounted[sensor - 1], yaw(scan.at("/data/pose/orientation"))), 0.01,
                            topic + " points where its sensor is mounted: " + scan);
                }

                // each topic's messages in the order of their timestamps, which are the ones in their data (topics
                // fed from different places, such as frames that pass through the space, may interleave by up to
                // a frame; the protocol orders by timestamp within a channel, and so do the viewers)
                List<JsonNode> messages = client.events("message");
                assertTrue(messages.size() >= 20, "frames for a second at least: " + messages.size());
                Map<String, Long> previous = new HashMap<>();
                for (JsonNode message : messages) {
                    long time = receiveTime(message);
                    String topic = message.path("topic").asText();
                    long before = previous.getOrDefault(topic, 0L);
                    assertTrue(time >= before, topic + " in timestamp order: " + time + " after " + before);
                    previous.put(topic, time);
                    assertEquals(time, message.at("/data/timestamp/sec").asLong() * 1_000_000_000L
                            + message.at("/data/timestamp/nsec").asLong(), message.toString());
                }
            } finally {
                tap.close();
            }
        }
    }

    /** The simulator's pose once two readings 200 ms apart agree (within 10 s). */
    private static Pose standingStill(SimWorld world) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        Pose before = world.robot().pose();
        while (true) {
            Thread.sleep(200);
            Pose now = world.robot().pose();
            if (now.equals(before)) {
                return now;
            }
            assertTrue(System.nanoTime() < deadline, "the robot did not stop: " + now);
            before = now;
        }
    }

    private static long receiveTime(JsonNode message) {
        return Long.parseLong(message.path("receiveTime").asText("0"));
    }

    /** The heading, in degrees, of a rotation about z given as a quaternion. */
    private static double yaw(JsonNode orientation) {
        return Math.toDegrees(2 * Math.atan2(orientation.get("z").asDouble(), orientation.get("w").asDouble()));
    }

    /** The difference of two headings in degrees, -180..180. */
    private static double angleBetween(double a, double b) {
        return Math.IEEEremainder(a - b, 360);
    }

    private static Set<String> topics(JsonNode advertise) {
        return java.util.stream.StreamSupport.stream(advertise.get("channels").spliterator(), false)
                .map(c -> c.get("topic").asText()).collect(Collectors.toSet());
    }

    private static void awaitSubscriptions(FoxgloveBridge bridge, int count) throws InterruptedException {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (bridge.subscriptionCount() < count) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("the client subscribed to " + bridge.subscriptionCount() + " channels");
            }
            Thread.sleep(20);
        }
    }
}
