package robotworld.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.observe.AnswerSeen;
import robotworld.observe.GroundTruth;
import robotworld.observe.ReplayMark;
import robotworld.observe.RequestSeen;
import robotworld.observe.WorldObserver;
import robotworld.observe.WorldTap;
import robotworld.recording.mcap.Channel;
import robotworld.recording.mcap.DataRecord;
import robotworld.recording.mcap.McapPeer;
import robotworld.recording.mcap.McapReader;
import robotworld.recording.mcap.Message;
import robotworld.recording.mcap.Summary;
import robotworld.space.EmbeddedSpace;
import robotworld.telemetry.Schemas;
import robotworld.telemetry.TrafficJson;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMIRDistanceModuleRemote;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * Recording a running simulated world, reading the file with our reader and the reference Python reader, and
 * replaying it (and a file written by the reference writer) into a space watched by a tap.
 */
class RecordingTest {

    @TempDir
    Path temp;

    /** Records {@code calls} of a laptop driving and reading SimBot; returns the file. */
    private Path record(SimWorld world, int rounds) throws Exception {
        Path file = temp.resolve("run.mcap");
        Recorder recorder = Recorder.start(file, new Recorder.Start(SimWorld.LAYOUT, world.url(),
                "<RobotWorld/>".getBytes()), Recorder.Options.defaults());
        // the tap hears of a request and of its answer through two subscriptions, in either order: count both
        java.util.concurrent.atomic.AtomicInteger motorRequests = new java.util.concurrent.atomic.AtomicInteger();
        java.util.concurrent.atomic.AtomicInteger motorAnswers = new java.util.concurrent.atomic.AtomicInteger();
        WorldTap tap = new WorldTap(world.space(), SimWorld.LAYOUT).add(recorder.observer())
                .add(new robotworld.observe.WorldObserver() {
                    @Override
                    public void requestSeen(robotworld.observe.RequestSeen event) {
                        if (event.module().name().equals("Motor")) {
                            motorRequests.incrementAndGet();
                        }
                    }

                    @Override
                    public void answerSeen(robotworld.observe.AnswerSeen event) {
                        if (event.module().name().equals("Motor")) {
                            motorAnswers.incrementAndGet();
                        }
                    }
                }).start();
        XVSMRuntime laptop = world.host("laptop");
        XVSMMotorModuleRemote motor = new XVSMMotorModuleRemote(laptop, SimWorld.ROBOT, "Motor");
        XVSMBumperModuleRemote bumper = new XVSMBumperModuleRemote(laptop, SimWorld.ROBOT, "Bumper");
        XVSMIRDistanceModuleRemote ir = new XVSMIRDistanceModuleRemote(laptop, SimWorld.ROBOT, "IR");
        for (int i = 1; i <= rounds; i++) {
            motor.setMotor(1, i / 100.0);
            bumper.getAllBumper();
            ir.getSingleSensor(1);
        }
        motor.setMotor(1, 0);
        // every motor request and answer reach the tap (and so the recorder, which hears of them first), and at least
        // a few ground-truth frames
        waitFor(() -> motorRequests.get() > rounds && motorAnswers.get() > rounds
                && recorder.status().messages() >= 6L * rounds + 20);
        tap.close();
        recorder.close("test done");
        assertEquals(0, recorder.status().dropped());
        return file;
    }

    @Test
    void aRecordingHoldsEveryCallAndTheGroundTruthAndTheReferenceReaderReadsItAll() throws Exception {
        Path file;
        try (SimWorld world = SimWorld.start()) {
            file = record(world, 20);
        }
        List<JsonNode> motorTraffic = new ArrayList<>();
        long frames = 0;
        long ours;
        try (McapReader reader = McapReader.open(file)) {
            Summary summary = reader.summary().orElseThrow();
            ours = summary.statistics().messageCount();
            List<String> topics = summary.channels().stream().map(Channel::topic).toList();
            for (String expected : List.of("/SimBot/Motor", "/SimBot/Bumper", "/SimBot/IR", "/rwe/liveness",
                    "/rwe/stops", "/rwe/gaps", "/SimBot/ground_truth", "/SimBot/scene", "/SimBot/pose", "/tf",
                    "/SimBot/ir/4.1")) {
                assertTrue(topics.contains(expected), expected + " in " + topics);
            }
            Map<Integer, String> topicOf = new HashMap<>();
            summary.channels().forEach(c -> topicOf.put(c.id(), c.topic()));
            McapReader.Cursor cursor = reader.cursor();
            for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
                if (record instanceof Message message) {
                    String topic = topicOf.get(message.channelId());
                    if (topic.equals("/SimBot/Motor")) {
                        motorTraffic.add(TrafficJson.parse(message.data()));
                    } else if (topic.equals("/SimBot/ground_truth")) {
                        frames++;
                    }
                }
            }
            assertEquals("<RobotWorld/>", new String(reader.attachment(RecordingFormat.WORLD_ATTACHMENT)
                    .orElseThrow().data()));
            assertEquals("test done", reader.metadata(RecordingFormat.END_METADATA).orElseThrow().values()
                    .get("why"));
        }
        // every motor call: its request then its answer, in order, with the speed in per-mille
        List<JsonNode> answers = motorTraffic.stream().filter(n -> n.get("kind").asText().equals("answer")).toList();
        assertEquals(21, answers.size(), motorTraffic.toString());
        for (int i = 0; i < 20; i++) {
            assertEquals("setMotor", answers.get(i).get("function").asText());
            assertEquals(1, answers.get(i).at("/fields/0").asInt());
            assertEquals((i + 1) * 10, answers.get(i).at("/fields/1").asInt());
            JsonNode latency = answers.get(i).get("latency_ms");
            assertTrue(latency.isNull() || latency.asDouble() > 0, latency.toString());
        }
        // the tap sees a request and its answer through two containers, so an answer may come first (then its
        // latency is unknown); most have one
        assertTrue(answers.stream().filter(a -> !a.get("latency_ms").isNull()).count() >= 10, answers.toString());
        assertEquals(21, motorTraffic.stream().filter(n -> n.get("kind").asText().equals("request")).count());
        assertTrue(frames >= 3, "ground-truth frames: " + frames);

        JsonNode found = McapPeer.require().read(file);
        assertEquals(ours, found.at("/summary/statistics/message_count").asLong());
        assertEquals(ours, found.get("indexed").size());
        assertEquals(ours, found.get("streamed").size());
        assertTrue(found.get("footer").asBoolean());
        assertTrue(found.at("/summary/chunk_indexes").asInt() >= 1);
        for (JsonNode schema : found.at("/summary/schemas")) {
            assertEquals("jsonschema", schema.get("encoding").asText());
            assertEquals(Schemas.text(schema.get("name").asText()), schema.get("data").asText());
        }
        List<String> pythonMotor = new ArrayList<>();
        for (JsonNode message : found.get("indexed")) {
            if (message.get("topic").asText().equals("/SimBot/Motor")) {
                pythonMotor.add(message.get("data").asText());
            }
        }
        // the reference reader hands messages over in log-time order; an answer the tap saw before its request
        // (through the other container) has the earlier log time, though it was written after it: same messages
        assertEquals(motorTraffic.stream().map(TrafficJson::bytes).map(String::new).sorted().toList(),
                pythonMotor.stream().sorted().toList());
    }

    @Test
    void aReplayShowsTheSameCallsInTheSameOrderMarkedAsAReplay() throws Exception {
        Path file;
        try (SimWorld world = SimWorld.start()) {
            file = record(world, 10);
        }
        List<String> recorded = new ArrayList<>();
        List<Long> recordedFrames = new ArrayList<>();
        try (McapReader reader = McapReader.open(file)) {
            Map<Integer, String> schemaOf = new HashMap<>();
            Summary summary = reader.summary().orElseThrow();
            summary.channels().forEach(c -> schemaOf.put(c.id(), summary.schema(c.schemaId()).name()));
            McapReader.Cursor cursor = reader.cursor();
            for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
                if (record instanceof Message m && schemaOf.get(m.channelId()).equals("rwe.GroundTruth")) {
                    recordedFrames.add(TrafficJson.parse(m.data()).get("sequence").asLong());
                }
                if (record instanceof Message m && schemaOf.get(m.channelId()).equals("rwe.ModuleTraffic")) {
                    TrafficJson.Traffic t = TrafficJson.traffic(TrafficJson.parse(m.data()));
                    recorded.add(t.module().name() + " " + (t.kind().equals("request") ? "request" : "answer") + " "
                            + t.call());
                }
            }
        }
        Collected seen = new Collected();
        try (EmbeddedSpace space = EmbeddedSpace.open(); Replayer replayer = Replayer.open(file)) {
            assertEquals(SimWorld.LAYOUT, replayer.layout());
            Replayer.Options options = new Replayer.Options(4, false);
            replayer.prepare(space, options);
            WorldTap tap = new WorldTap(space, replayer.layout()).add(seen).start();
            try {
                replayer.play(space, options, progress -> { });
                waitFor(() -> seen.traffic.size() >= recorded.size() && seen.frames.size() >= recordedFrames.size());
            } finally {
                tap.close();
            }
            assertTrue(ReplayMark.find(space).isPresent());
        }
        assertNotNull(seen.mark);
        assertEquals("run.mcap", seen.mark.recording());
        // each container's events arrive in order (requests and answers travel through two containers, so
        // their interleaving is not kept, live or replayed)
        for (String module : List.of("Motor", "Bumper", "IR")) {
            for (String kind : List.of(" request ", " answer ")) {
                assertEquals(only(recorded, module + kind), only(seen.traffic, module + kind), module + kind);
            }
        }
        assertEquals(recorded.size(), seen.traffic.size());
        assertTrue(!recordedFrames.isEmpty(), "the simulator's frames were recorded");
        assertEquals(recordedFrames, seen.frames.stream().map(GroundTruth::sequence).toList(), "every frame, in order");
    }

    @Test
    void aFileWrittenByTheReferenceWriterWithOurSchemasReplays() throws Exception {
        McapPeer peer = McapPeer.require();
        ObjectNode spec = TrafficJson.MAPPER.createObjectNode();
        spec.put("compression", "none");
        ArrayNode schemas = spec.putArray("schemas");
        for (String name : List.of("rwe.ModuleTraffic", "rwe.GroundTruth")) {
            schemas.addObject().put("name", name).put("encoding", "jsonschema").put("data", Schemas.text(name));
        }
        ArrayNode channels = spec.putArray("channels");
        channels.addObject().put("topic", "/Bot/Wheels").put("message_encoding", "json")
                .put("schema", "rwe.ModuleTraffic");
        channels.addObject().put("topic", "/Bot/ground_truth").put("message_encoding", "json")
                .put("schema", "rwe.GroundTruth");
        ArrayNode messages = spec.putArray("messages");
        long t0 = 1_700_000_000_000_000_000L;
        for (int i = 0; i < 5; i++) {
            ObjectNode request = TrafficJson.MAPPER.createObjectNode().put("kind", "request").put("participant", "Bot")
                    .put("module", "Wheels").put("module_class", "MotorModule").put("key", "pc#" + i)
                    .put("function", "setMotor");
            request.putArray("fields").add(2).add(100 * i);
            messages.addObject().put("topic", "/Bot/Wheels").put("log_time", t0 + i * 20_000_000L)
                    .put("data", request.toString());
            ObjectNode answer = request.deepCopy().put("kind", "answer");
            messages.addObject().put("topic", "/Bot/Wheels").put("log_time", t0 + i * 20_000_000L + 5_000_000L)
                    .put("data", answer.toString());
        }
        GroundTruth frame = new GroundTruth("Bot", 1, java.time.Instant.ofEpochSecond(0, t0), 0.5,
                new GroundTruth.Arena(1000, 800, List.of(new GroundTruth.Obstacle(10, 20, 30, 40))),
                new GroundTruth.Body(100, 200, 45, 150), List.of(), List.of(), List.of());
        messages.addObject().put("topic", "/Bot/ground_truth").put("log_time", t0 + 150_000_000L)
                .put("data", TrafficJson.groundTruth(frame).toString());
        Path file = temp.resolve("theirs.mcap");
        peer.write(file, spec, temp);

        Collected seen = new Collected();
        try (EmbeddedSpace space = EmbeddedSpace.open(); Replayer replayer = Replayer.open(file)) {
            assertEquals(List.of("Bot"), replayer.layout().participants().stream().map(p -> p.name()).toList());
            assertFalse(replayer.worldDescription().isPresent());
            Replayer.Options options = new Replayer.Options(10, false);
            replayer.prepare(space, options);
            WorldTap tap = new WorldTap(space, replayer.layout()).add(seen).start();
            try {
                replayer.play(space, options, progress -> { });
                waitFor(() -> seen.traffic.size() >= 10 && !seen.frames.isEmpty());
            } finally {
                tap.close();
            }
        }
        List<String> answers = only(seen.traffic, "Wheels answer ");
        assertEquals(5, answers.size());
        List<String> requests = only(seen.traffic, "Wheels request ");
        assertEquals(5, requests.size());
        // in order within each container; a request and its answer, 0.5 ms apart at rate 10, reach the tap through
        // two subscriptions, whose events a busy machine may interleave either way
        assertEquals("Wheels request <\"pc#0\", 2, 0, \"setMotor\">", requests.get(0));
        assertEquals("Wheels request <\"pc#4\", 2, 400, \"setMotor\">", requests.get(4));
        assertEquals("Wheels answer <\"pc#0\", 2, 0, \"setMotor\">", answers.get(0));
        assertEquals("Wheels answer <\"pc#4\", 2, 400, \"setMotor\">", answers.get(4));
        assertEquals(new GroundTruth.Body(100, 200, 45, 150), seen.frames.get(0).body());
    }

    @Test
    void whatTheRecorderCannotKeepIsCountedAndWrittenDown() throws Exception {
        Path file = temp.resolve("burst.mcap");
        Recorder recorder = Recorder.start(file, new Recorder.Start(SimWorld.LAYOUT, "http://nowhere", null),
                Recorder.Options.defaults().queueCapacity(1));
        int offered = 100_000;
        int accepted = 0;
        byte[] json = "{\"participant\":\"SimBot\",\"state\":\"ALIVE\"}".getBytes();
        for (int i = 0; i < offered; i++) {
            if (recorder.offer(new robotworld.telemetry.TelemetryMessage(robotworld.telemetry.Topics.LIVENESS,
                    i, json))) {
                accepted++;
            }
        }
        Recorder.Status during = recorder.status();
        recorder.close();
        long dropped = offered - accepted;
        assertTrue(dropped > 0, "a one-message queue under a burst drops");
        assertEquals(dropped, recorder.status().dropped());
        assertTrue(during.dropped() > 0, during.toString());
        long reported = 0;
        long liveness = 0;
        try (McapReader reader = McapReader.open(file)) {
            Map<Integer, String> topicOf = new HashMap<>();
            reader.summary().orElseThrow().channels().forEach(c -> topicOf.put(c.id(), c.topic()));
            McapReader.Cursor cursor = reader.cursor();
            for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
                if (record instanceof Message m && topicOf.get(m.channelId()).equals("/rwe/gaps")) {
                    reported += TrafficJson.parse(m.data()).get("missed").asLong();
                } else if (record instanceof Message m && topicOf.get(m.channelId()).equals("/rwe/liveness")) {
                    liveness++;
                }
            }
            assertEquals(String.valueOf(dropped), reader.metadata(RecordingFormat.END_METADATA).orElseThrow()
                    .values().get("dropped"));
        }
        assertEquals(dropped, reported, "every drop is in the file");
        assertEquals(accepted, liveness, "every accepted message is in the file");
    }

    private static List<String> only(List<String> traffic, String prefix) {
        return traffic.stream().filter(line -> line.startsWith(prefix)).toList();
    }

    @Test
    void stopRecordsAndHeartbeatsAreRecordedAndTheStopsReplay() throws Exception {
        Path file = temp.resolve("stops.mcap");
        robotworld.safety.StopRecord stop = new robotworld.safety.StopRecord(java.time.Instant.ofEpochMilli(
                1_764_000_000_123L), "SimBot", "Motor", robotworld.safety.StopCause.COMMANDER_SILENT,
                "laptop#k3x9 silent for 512 ms", "motors 1-8 set to 0", "robot-pc#q1w2", "laptop#k3x9", "");
        try (EmbeddedSpace live = EmbeddedSpace.open()) {
            Recorder recorder = Recorder.start(file, new Recorder.Start(SimWorld.LAYOUT, "embedded", null),
                    Recorder.Options.defaults());
            WorldTap tap = new WorldTap(live, SimWorld.LAYOUT).add(recorder.observer()).start();
            robotworld.telemetry.SafetyTelemetry safety = robotworld.telemetry.SafetyTelemetry.start(live,
                    recorder::offer);
            live.shift(robotworld.safety.SafetyContainers.liveness(live), robotworld.space.Timeout.TRY_ONCE,
                    List.of(robotworld.space.Item.keyed("robot-pc#q1w2", new robotworld.safety.Heartbeat(
                            "robot-pc#q1w2", "robot-pc", List.of(new robotworld.safety.Heartbeat.ModuleName("SimBot",
                            "Motor")), false, 42, 100, 1_764_000_000_000L).toTuple())));
            live.shift(robotworld.safety.SafetyContainers.stops(live), robotworld.space.Timeout.TRY_ONCE,
                    stop.toTuple());
            waitFor(() -> recorder.status().messages() >= 2);
            safety.close();
            tap.close();
            recorder.close();
        }
        List<String> topics = new ArrayList<>();
        try (McapReader reader = McapReader.open(file)) {
            Map<Integer, String> topicOf = new HashMap<>();
            reader.summary().orElseThrow().channels().forEach(c -> topicOf.put(c.id(), c.topic()));
            McapReader.Cursor cursor = reader.cursor();
            for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
                if (record instanceof Message m) {
                    topics.add(topicOf.get(m.channelId()) + " " + m.text());
                }
            }
        }
        assertTrue(topics.stream().anyMatch(t -> t.startsWith("/rwe/heartbeats ") && t.contains("\"sequence\":42")
                && t.contains("SimBot/Motor")), topics.toString());
        assertTrue(topics.stream().anyMatch(t -> t.startsWith("/rwe/stop_records ")
                && t.contains("\"cause\":\"commander-silent\"")), topics.toString());

        List<robotworld.safety.StopRecord> replayed = new CopyOnWriteArrayList<>();
        try (EmbeddedSpace space = EmbeddedSpace.open(); Replayer replayer = Replayer.open(file)) {
            Replayer.Options options = new Replayer.Options(10, false);
            replayer.prepare(space, options);
            robotworld.safety.StopWatcher watcher = robotworld.safety.StopWatcher.start(space, replayed::add);
            try {
                replayer.play(space, options, progress -> { });
                waitFor(() -> !replayed.isEmpty());
            } finally {
                watcher.close();
            }
        }
        assertEquals(stop, replayed.get(0));
    }

    /** What a tap delivered: module traffic as "Module request|answer <tuple>", frames, the replay mark. */
    static final class Collected implements WorldObserver {
        final List<String> traffic = new CopyOnWriteArrayList<>();
        final List<GroundTruth> frames = new CopyOnWriteArrayList<>();
        volatile ReplayMark mark;

        @Override
        public void requestSeen(RequestSeen event) {
            traffic.add(event.module().name() + " request " + event.request());
        }

        @Override
        public void answerSeen(AnswerSeen event) {
            if (!event.earlier()) {
                traffic.add(event.module().name() + " answer " + event.answer());
            }
        }

        @Override
        public void groundTruth(GroundTruth frame) {
            frames.add(frame);
        }

        @Override
        public void replay(ReplayMark replay) {
            mark = replay;
        }
    }

    static void waitFor(BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("condition not met within 60 s");
            }
            Thread.sleep(20);
        }
    }
}
