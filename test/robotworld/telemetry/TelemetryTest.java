package robotworld.telemetry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldLayouts;
import robotworld.observe.GroundTruth;
import robotworld.observe.WorldLayout;
import robotworld.space.Entry;
import robotworld.space.Tuple;
import robotworld.testsupport.ProjectFiles;

/** The JSON forms of tuples and frames, the schemas, and the Foxglove layout shipped in docs/. */
class TelemetryTest {

    @Test
    void entriesAndFramesSurviveTheirJsonForm() throws Exception {
        Entry entry = Tuple.of(Long.MAX_VALUE, "ü \"quoted\"", Tuple.of(1L, Tuple.of()), -5L);
        assertEquals(entry, TrafficJson.entry(TrafficJson.parse(TrafficJson.bytes(TrafficJson.json(entry)))));
        assertThrows(IllegalArgumentException.class, () -> TrafficJson.entry(TrafficJson.parse("1.5".getBytes())));
        assertThrows(IllegalArgumentException.class, () -> TrafficJson.entry(TrafficJson.parse("true".getBytes())));

        GroundTruth frame = new GroundTruth("Bot", 7, Instant.parse("2026-11-23T10:00:00.123456789Z"), 1.5,
                new GroundTruth.Arena(1600, 1200, List.of(new GroundTruth.Obstacle(700, 400, 200, 400))),
                new GroundTruth.Body(350.5, 600, 12.25, 150),
                List.of(new GroundTruth.Ray(4, 1, 0, 320, 800)),
                List.of(new GroundTruth.Bumper(2, 4, 35, 70, true)),
                List.of(new GroundTruth.Motor(1, 1, 0.5, 0.25, "left")));
        JsonNode json = TrafficJson.groundTruth(frame);
        assertEquals(frame, TrafficJson.groundTruth(TrafficJson.parse(TrafficJson.bytes(json)), Instant.EPOCH));
        JsonNode scan = GroundTruthScene.scan(frame, frame.rays().get(0));
        assertEquals(0.32, scan.at("/ranges/0").asDouble(), 1e-9);
        assertEquals(0.15, scan.at("/pose/position/x").asDouble(), 1e-9, "from the body outline");
        JsonNode tf = GroundTruthScene.transforms(frame);
        assertEquals(0.3505, tf.at("/transforms/0/translation/x").asDouble(), 1e-9);
        assertEquals(Math.sin(Math.toRadians(12.25) / 2), tf.at("/transforms/0/rotation/z").asDouble(), 1e-9);
        assertEquals(123456789, tf.at("/transforms/0/timestamp/nsec").asInt());
    }

    @Test
    void everySchemaIsAJsonSchemaTitledWithItsName() throws Exception {
        for (String name : Schemas.NAMES) {
            JsonNode schema = TrafficJson.parse(Schemas.text(name).getBytes());
            assertEquals(name, schema.get("title").asText());
            assertEquals("object", schema.get("type").asText());
        }
    }

    @Test
    void theShippedFoxgloveLayoutNamesOnlyTopicsTheDemoWorldHas() throws Exception {
        WorldLayout layout = WorldLayouts.of(MonitoredWorld.of(DescriptionLoader.loadWorld(
                ProjectFiles.resolve("docs/examples/chapter5-world.xml"))));
        Set<String> offered = Topics.known(layout).stream().map(Topic::name).collect(Collectors.toSet());
        JsonNode file = TrafficJson.parse(Files.readAllBytes(ProjectFiles.resolve(
                "docs/foxglove/rwe-demo-layout.json")));
        List<String> named = new ArrayList<>();
        file.get("configById").forEach(panel -> {
            panel.path("topics").fieldNames().forEachRemaining(named::add);
            panel.path("paths").forEach(path -> named.add(topicOf(path.get("value").asText())));
            if (panel.has("topicPath")) {
                named.add(topicOf(panel.get("topicPath").asText()));
            }
        });
        assertTrue(named.size() >= 8, named.toString());
        for (String topic : named) {
            assertTrue(offered.contains(topic), topic + " is not offered; offered: " + offered);
        }
    }

    /** The topic of a message path: up to the first field access or filter. */
    private static String topicOf(String path) {
        int end = path.length();
        for (char stop : new char[] {'.', '{', '['}) {
            int at = path.indexOf(stop);
            if (at > 0) {
                end = Math.min(end, at);
            }
        }
        return path.substring(0, end);
    }
}
