package robotworld.telemetry;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.URI;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import robotworld.observe.ActuatorStopped;
import robotworld.observe.AnswerSeen;
import robotworld.observe.Gap;
import robotworld.observe.GroundTruth;
import robotworld.observe.Liveness;
import robotworld.observe.ModuleRef;
import robotworld.observe.RequestSeen;
import robotworld.space.ContainerRef;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;
import robotworld.xvsm.CallTuple;

/**
 * The {@code rwe.*} messages as JSON, both ways: events into messages (recording, Foxglove) and
 * {@code rwe.ModuleTraffic} / {@code rwe.GroundTruth} messages back into tuples and frames (replay).
 */
public final class TrafficJson {

    /** The one mapper (thread-safe once configured). */
    public static final ObjectMapper MAPPER = new ObjectMapper();
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    /** A module message: request, answer or error, and the module it concerns, with the exact call. */
    public record Traffic(String kind, ModuleRef module, CallTuple call) {
    }

    private TrafficJson() {
    }

    /** A request as {@code rwe.ModuleTraffic}. */
    public static ObjectNode request(RequestSeen event) {
        ObjectNode node = traffic("request", event.module(), event.request());
        node.put("queued", event.queued());
        return node;
    }

    /** An answer (or error answer) as {@code rwe.ModuleTraffic}. */
    public static ObjectNode answer(AnswerSeen event) {
        ObjectNode node = traffic(event.isError() ? "error" : "answer", event.module(), event.answer());
        node.put("queued", event.queued());
        if (event.latency() == null) {
            node.putNull("latency_ms");
        } else {
            node.put("latency_ms", event.latency().toNanos() / 1e6);
        }
        node.put("earlier", event.earlier());
        node.put("remote", event.isRemoteCall());
        return node;
    }

    private static ObjectNode traffic(String kind, ModuleRef module, CallTuple call) {
        ObjectNode node = NODES.objectNode();
        node.put("kind", kind);
        node.put("participant", module.participant());
        node.put("module", module.name());
        node.put("module_class", module.moduleClass());
        node.put("key", call.key());
        int hash = call.key().indexOf('#');
        node.put("host", hash < 0 ? call.key() : call.key().substring(0, hash));
        node.set("function", json(call.function()));
        ArrayNode fields = node.putArray("fields");
        call.fields().forEach(field -> fields.add(json(field)));
        return node;
    }

    /** Liveness as {@code rwe.Liveness}. */
    public static ObjectNode liveness(Liveness event) {
        ObjectNode node = NODES.objectNode();
        node.put("participant", event.participant());
        node.put("state", event.state().name());
        node.put("alive", event.state() == Liveness.State.ALIVE ? 1 : 0);
        if (event.lastSign() == null) {
            node.putNull("last_sign");
        } else {
            node.put("last_sign", event.lastSign().toString());
        }
        node.put("basis", event.basis());
        return node;
    }

    /** A stop as {@code rwe.ActuatorStopped}. */
    public static ObjectNode stopped(ActuatorStopped event) {
        ObjectNode node = NODES.objectNode();
        node.put("participant", event.module().participant());
        node.put("module", event.module().name());
        node.put("module_class", event.module().moduleClass());
        node.put("by", event.by());
        return node;
    }

    /** A gap as {@code rwe.Gap}. */
    public static ObjectNode gap(Gap gap) {
        ObjectNode node = NODES.objectNode();
        if (gap.module() == null) {
            node.putNull("participant");
            node.putNull("module");
        } else {
            node.put("participant", gap.module().participant());
            node.put("module", gap.module().name());
        }
        node.put("missed", gap.missed());
        node.put("why", gap.why());
        node.put("ended", gap.ended());
        return node;
    }

    /** A frame as {@code rwe.GroundTruth}. */
    public static ObjectNode groundTruth(GroundTruth frame) {
        ObjectNode node = NODES.objectNode();
        node.put("robot", frame.robot());
        node.put("sequence", frame.sequence());
        node.put("time", frame.at().toString());
        node.put("simulated_seconds", frame.simulatedSeconds());
        ObjectNode arena = node.putObject("arena");
        arena.put("width", frame.arena().width());
        arena.put("height", frame.arena().height());
        ArrayNode obstacles = arena.putArray("obstacles");
        for (GroundTruth.Obstacle o : frame.arena().obstacles()) {
            obstacles.addObject().put("x", o.x()).put("y", o.y()).put("width", o.width()).put("height", o.height());
        }
        GroundTruth.Body body = frame.body();
        node.putObject("body").put("x", body.x()).put("y", body.y()).put("heading", body.heading())
                .put("radius", body.radius());
        ArrayNode rays = node.putArray("rays");
        for (GroundTruth.Ray r : frame.rays()) {
            rays.addObject().put("address", r.address()).put("sensor", r.sensor()).put("angle", r.angle())
                    .put("length", r.length()).put("range", r.range()).put("hits", r.hits());
        }
        ArrayNode bumpers = node.putArray("bumpers");
        for (GroundTruth.Bumper b : frame.bumpers()) {
            bumpers.addObject().put("address", b.address()).put("number", b.number()).put("angle", b.angle())
                    .put("span", b.span()).put("contact", b.contact());
        }
        ArrayNode motors = node.putArray("motors");
        for (GroundTruth.Motor m : frame.motors()) {
            motors.addObject().put("address", m.address()).put("channel", m.channel()).put("set_point", m.setPoint())
                    .put("actual", m.actual()).put("wheel", m.wheel());
        }
        node.put("any_contact", frame.anyContact());
        return node;
    }

    /** An entry as JSON: integers as numbers, strings as strings, tuples as arrays, crefs as {"cref": ...}. */
    public static JsonNode json(Entry entry) {
        if (entry instanceof IntEntry number) {
            return NODES.numberNode(number.value());
        }
        if (entry instanceof StringEntry text) {
            return NODES.textNode(text.value());
        }
        if (entry instanceof Tuple tuple) {
            ArrayNode array = NODES.arrayNode();
            tuple.fields().forEach(field -> array.add(json(field)));
            return array;
        }
        ContainerRef cref = (ContainerRef) entry;
        ObjectNode node = NODES.objectNode();
        node.putObject("cref").put("space", cref.space().toString()).put("id", cref.id());
        return node;
    }

    /**
     * Reads an entry written by {@link #json(Entry)}.
     *
     * @throws IllegalArgumentException for JSON that is no entry (a fraction, a boolean, null, another object)
     */
    public static Entry entry(JsonNode node) {
        if (node.isIntegralNumber() && node.canConvertToLong()) {
            return new IntEntry(node.longValue());
        }
        if (node.isTextual()) {
            return new StringEntry(node.textValue());
        }
        if (node.isArray()) {
            List<Entry> fields = new ArrayList<>(node.size());
            node.forEach(field -> fields.add(entry(field)));
            return new Tuple(fields);
        }
        if (node.isObject() && node.has("cref") && node.get("cref").isObject()) {
            JsonNode cref = node.get("cref");
            return new ContainerRef(URI.create(text(cref, "space")), text(cref, "id"));
        }
        throw new IllegalArgumentException("not a space entry (integer, string, array or {\"cref\": ...}): " + node);
    }

    /**
     * Reads an {@code rwe.ModuleTraffic} message.
     *
     * @throws IllegalArgumentException when a required field is missing or of the wrong kind
     */
    public static Traffic traffic(JsonNode node) {
        String kind = text(node, "kind");
        if (!kind.equals("request") && !kind.equals("answer") && !kind.equals("error")) {
            throw new IllegalArgumentException("kind must be request, answer or error, was " + kind);
        }
        ModuleRef module = new ModuleRef(text(node, "participant"), text(node, "module"), text(node, "module_class"));
        JsonNode function = node.get("function");
        if (function == null || !(function.isTextual() || function.isIntegralNumber())) {
            throw new IllegalArgumentException("function must be a string or an integer: " + node);
        }
        JsonNode fields = node.get("fields");
        if (fields == null || !fields.isArray()) {
            throw new IllegalArgumentException("fields must be an array: " + node);
        }
        List<Entry> values = new ArrayList<>();
        fields.forEach(field -> values.add(entry(field)));
        return new Traffic(kind, module, new CallTuple(text(node, "key"), values, entry(function)));
    }

    /**
     * Reads an {@code rwe.GroundTruth} message; {@code at} is the frame's time when the message has none.
     *
     * @throws IllegalArgumentException when a required field is missing or of the wrong kind
     */
    public static GroundTruth groundTruth(JsonNode node, Instant at) {
        JsonNode arena = object(node, "arena");
        List<GroundTruth.Obstacle> obstacles = new ArrayList<>();
        for (JsonNode o : array(arena, "obstacles")) {
            obstacles.add(new GroundTruth.Obstacle(number(o, "x"), number(o, "y"), number(o, "width"),
                    number(o, "height")));
        }
        List<GroundTruth.Ray> rays = new ArrayList<>();
        for (JsonNode r : array(node, "rays")) {
            rays.add(new GroundTruth.Ray((int) number(r, "address"), (int) number(r, "sensor"), number(r, "angle"),
                    number(r, "length"), number(r, "range")));
        }
        List<GroundTruth.Bumper> bumpers = new ArrayList<>();
        for (JsonNode b : array(node, "bumpers")) {
            bumpers.add(new GroundTruth.Bumper((int) number(b, "address"), (int) number(b, "number"),
                    number(b, "angle"), number(b, "span"), b.path("contact").asBoolean()));
        }
        List<GroundTruth.Motor> motors = new ArrayList<>();
        for (JsonNode m : array(node, "motors")) {
            motors.add(new GroundTruth.Motor((int) number(m, "address"), (int) number(m, "channel"),
                    number(m, "set_point"), number(m, "actual"), m.path("wheel").asText("")));
        }
        JsonNode body = object(node, "body");
        Instant time = node.hasNonNull("time") ? Instant.parse(node.get("time").asText()) : at;
        return new GroundTruth(text(node, "robot"), (long) number(node, "sequence"), time,
                node.path("simulated_seconds").asDouble(0), new GroundTruth.Arena(number(arena, "width"),
                number(arena, "height"), obstacles), new GroundTruth.Body(number(body, "x"), number(body, "y"),
                number(body, "heading"), number(body, "radius")), rays, bumpers, motors);
    }

    /** Parses UTF-8 JSON. */
    public static JsonNode parse(byte[] json) throws IOException {
        return MAPPER.readTree(json);
    }

    /** The node as UTF-8 JSON. */
    public static byte[] bytes(JsonNode node) {
        try {
            return MAPPER.writeValueAsBytes(node);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a JSON tree that cannot be written: " + e.getMessage(), e);
        }
    }

    private static String text(JsonNode node, String field) {
        JsonNode value = node.get(field);
        if (value == null || !value.isTextual()) {
            throw new IllegalArgumentException("\"" + field + "\" must be a string: " + node);
        }
        return value.textValue();
    }

    private static double number(JsonNode node, String field) {
        JsonNode value = node.get(field);
        if (value == null || !value.isNumber()) {
            throw new IllegalArgumentException("\"" + field + "\" must be a number: " + node);
        }
        return value.doubleValue();
    }

    private static JsonNode object(JsonNode node, String field) {
        JsonNode value = node.get(field);
        if (value == null || !value.isObject()) {
            throw new IllegalArgumentException("\"" + field + "\" must be an object: " + node);
        }
        return value;
    }

    private static JsonNode array(JsonNode node, String field) {
        JsonNode value = node.get(field);
        if (value == null || !value.isArray()) {
            throw new IllegalArgumentException("\"" + field + "\" must be an array: " + node);
        }
        return value;
    }
}
