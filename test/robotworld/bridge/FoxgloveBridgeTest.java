package robotworld.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import robotworld.observe.WorldTap;
import robotworld.recording.SimWorld;
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
