package robotworld.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.explorer.cli.Rwe;
import robotworld.observe.AnswerSeen;
import robotworld.observe.WorldObserver;
import robotworld.observe.WorldTap;
import robotworld.recording.mcap.DataRecord;
import robotworld.recording.mcap.McapPeer;
import robotworld.recording.mcap.McapReader;
import robotworld.recording.mcap.Message;
import robotworld.space.EmbeddedSpace;
import robotworld.telemetry.TrafficJson;
import robotworld.xvsm.ModuleCallTimeoutException;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * A call that fails at the module's host (its bumper hardware does not answer) is recorded as an error answer,
 * read back by both readers, counted by {@code rwe record --info}, and replayed so a watcher sees the error.
 */
class ErrorAnswerRecordingTest {

    private static final String BUMPER_TOPIC = "/SimBot/Bumper";

    @TempDir
    Path temp;

    @Test
    void aFailedCallIsRecordedAsAnErrorAnswerAndReplayedAsOne() throws Exception {
        Path file = recordAFailingBumperRead();

        // our reader: the bumper's channel holds the request and the error answer the host sent
        List<JsonNode> bumper = bumperTraffic(file);
        assertEquals(List.of("request", "error"), bumper.stream().map(m -> m.get("kind").asText()).toList());
        JsonNode error = bumper.get(1);
        assertEquals("ERROR", error.get("function").asText());
        assertEquals("getAllBumper", error.at("/fields/0").asText());
        assertEquals("timeout", error.at("/fields/1/0").asText(), "the hardware did not answer: " + error);
        assertEquals("robot-pc", error.at("/fields/1/3").asText(), "the host serving the module: " + error);
        assertEquals(bumper.get(0).get("key"), error.get("key"), "the error answers that request");

        // the reference Python reader finds the same two messages, byte for byte
        JsonNode found = McapPeer.require().read(file);
        List<String> pythonBumper = new ArrayList<>();
        for (JsonNode message : found.get("indexed")) {
            if (message.get("topic").asText().equals(BUMPER_TOPIC)) {
                pythonBumper.add(message.get("data").asText());
            }
        }
        assertEquals(bumper.stream().map(TrafficJson::bytes).map(String::new).toList(), pythonBumper);

        // rwe record --info counts it on the bumper's channel
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(0, Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), "record", "--info",
                file.toString()), err.toString());
        assertTrue(out.toString().matches("(?s).*" + BUMPER_TOPIC + "\\s+rwe.ModuleTraffic\\s+json\\s+2\\n.*"),
                out.toString());

        // a replay puts the same error answer where the caller took it from: a watcher sees the failure
        String recordedError = TrafficJson.traffic(error).call().toString();
        RecordingTest.Collected seen = new RecordingTest.Collected();
        List<AnswerSeen> errors = new CopyOnWriteArrayList<>();
        try (EmbeddedSpace space = EmbeddedSpace.open(); Replayer replayer = Replayer.open(file)) {
            Replayer.Options options = new Replayer.Options(10, false);
            replayer.prepare(space, options);
            WorldTap tap = new WorldTap(space, replayer.layout()).add(seen).add(new WorldObserver() {
                @Override
                public void answerSeen(AnswerSeen event) {
                    if (event.isError()) {
                        errors.add(event);
                    }
                }
            }).start();
            try {
                replayer.play(space, options, progress -> { });
                RecordingTest.waitFor(() -> !errors.isEmpty()
                        && seen.traffic.stream().filter(t -> t.startsWith("Bumper ")).count() >= 2);
            } finally {
                tap.close();
            }
        }
        assertEquals(1, errors.size(), errors.toString());
        assertEquals(SimWorld.BUMPER, errors.get(0).module());
        assertEquals(recordedError, errors.get(0).answer().toString());
        // with its request (the two travel through two containers, so the tap may hear of them in either order)
        assertEquals(Set.of("Bumper request " + TrafficJson.traffic(bumper.get(0)).call(),
                "Bumper answer " + recordedError), Set.copyOf(seen.traffic.stream()
                        .filter(t -> t.startsWith("Bumper ")).toList()));
    }

    /** Records a motor call that succeeds and a bumper read that fails because the bumper hardware is silent. */
    private Path recordAFailingBumperRead() throws Exception {
        Path file = temp.resolve("failing.mcap");
        try (SimWorld world = SimWorld.start()) {
            Recorder recorder = Recorder.start(file, new Recorder.Start(SimWorld.LAYOUT, world.url(), null),
                    Recorder.Options.defaults());
            AtomicInteger errorsSeen = new AtomicInteger();
            WorldTap tap = new WorldTap(world.space(), SimWorld.LAYOUT).add(recorder.observer())
                    .add(new WorldObserver() {
                        @Override
                        public void answerSeen(AnswerSeen event) {
                            if (event.isError()) {
                                errorsSeen.incrementAndGet();
                            }
                        }
                    }).start();
            XVSMRuntime laptop = world.host("laptop");
            new XVSMMotorModuleRemote(laptop, SimWorld.ROBOT, "Motor").setMotor(1, 0.2);
            world.robot().faults(2).silent(true);
            XVSMBumperModuleRemote bumper = new XVSMBumperModuleRemote(laptop, SimWorld.ROBOT, "Bumper");
            assertThrows(ModuleCallTimeoutException.class, bumper::getAllBumper, "the caller learns of the failure");
            RecordingTest.waitFor(() -> errorsSeen.get() == 1); // the recorder hears of it first
            tap.close();
            recorder.close("test done");
            assertEquals(0, recorder.status().dropped());
        }
        return file;
    }

    private static List<JsonNode> bumperTraffic(Path file) throws Exception {
        List<JsonNode> traffic = new ArrayList<>();
        try (McapReader reader = McapReader.open(file)) {
            Map<Integer, String> topicOf = new HashMap<>();
            reader.summary().orElseThrow().channels().forEach(c -> topicOf.put(c.id(), c.topic()));
            McapReader.Cursor cursor = reader.cursor();
            for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
                if (record instanceof Message m && topicOf.get(m.channelId()).equals(BUMPER_TOPIC)) {
                    traffic.add(TrafficJson.parse(m.data()));
                }
            }
        }
        return traffic;
    }
}
