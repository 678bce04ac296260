package robotworld.recording;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import robotworld.observe.ModuleRef;
import robotworld.observe.WorldLayout;
import robotworld.telemetry.TrafficJson;

/** The names of what a recording carries besides its messages, and the layout as JSON. */
public final class RecordingFormat {

    /** Metadata written when recording starts: world, started, space, host, recorder. */
    public static final String START_METADATA = "rwe.recording";
    /** Metadata written when recording ends: ended, messages, dropped, why it ended. */
    public static final String END_METADATA = "rwe.recording.end";
    /** The world's layout as JSON ({@link #layoutJson}). */
    public static final String LAYOUT_ATTACHMENT = "rwe-layout.json";
    /** The world's description, when the recorder had it. */
    public static final String WORLD_ATTACHMENT = "world.xml";
    /** The value of the {@code format} key of the start metadata. */
    public static final String FORMAT = "rwe-recording/1";

    private RecordingFormat() {
    }

    /** {@code {"world": ..., "participants": [{"name", "kind", "modules": [{"name", "class"}]}]}}. */
    public static byte[] layoutJson(WorldLayout layout) {
        ObjectNode root = TrafficJson.MAPPER.createObjectNode();
        root.put("world", layout.world());
        ArrayNode participants = root.putArray("participants");
        for (WorldLayout.Participant participant : layout.participants()) {
            ObjectNode node = participants.addObject();
            node.put("name", participant.name());
            node.put("kind", participant.kind());
            ArrayNode modules = node.putArray("modules");
            for (ModuleRef module : participant.modules()) {
                modules.addObject().put("name", module.name()).put("class", module.moduleClass());
            }
        }
        return TrafficJson.bytes(root);
    }

    /**
     * Reads {@link #layoutJson}.
     *
     * @throws IllegalArgumentException when it is not such a layout
     */
    public static WorldLayout layout(JsonNode root) {
        if (!root.path("world").isTextual() || !root.path("participants").isArray()) {
            throw new IllegalArgumentException("not a world layout: " + root);
        }
        List<WorldLayout.Participant> participants = new ArrayList<>();
        for (JsonNode node : root.get("participants")) {
            String name = node.path("name").asText();
            List<ModuleRef> modules = new ArrayList<>();
            for (JsonNode module : node.path("modules")) {
                modules.add(new ModuleRef(name, module.path("name").asText(), module.path("class").asText()));
            }
            participants.add(new WorldLayout.Participant(name, node.path("kind").asText("robot"), modules));
        }
        return new WorldLayout(root.get("world").asText(), participants);
    }
}
