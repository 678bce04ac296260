package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.space.Entry;
import robotworld.space.Tuple;

/** The tuple layouts of the safety containers, exactly as docs/runtime.md shows them: others read them. */
class SafetyLayoutTest {

    @Test
    void heartbeat() {
        Heartbeat heartbeat = new Heartbeat("robot-pc#q1w2", "robot-pc", List.of(
                new Heartbeat.ModuleName("CaterpillarRobot", "Motor-Controller"),
                new Heartbeat.ModuleName("CaterpillarRobot", "Bumper-Sensor")), false, 4711, 100, 1764000000123L);
        Tuple tuple = Tuple.of("robot-pc#q1w2", "robot-pc", Tuple.of(Tuple.of("CaterpillarRobot", "Motor-Controller"),
                Tuple.of("CaterpillarRobot", "Bumper-Sensor")), "alive", 4711, 100, 1764000000123L);
        assertEquals(tuple, heartbeat.toTuple());
        assertEquals(heartbeat, Heartbeat.parse(tuple));
        Heartbeat ended = new Heartbeat("laptop#k3x9", "laptop", List.of(), true, 12, 100, 5);
        assertEquals(Entry.of("ended"), ended.toTuple().get(3));
        assertEquals(ended, Heartbeat.parse(ended.toTuple()));
        assertThrows(IllegalArgumentException.class, () -> Heartbeat.parse(Tuple.of("robot-pc#q1w2", 4711)));
    }

    @Test
    void stopRecord() {
        StopRecord record = new StopRecord(Instant.ofEpochMilli(1764000000123L), "CaterpillarRobot",
                "Motor-Controller", StopCause.COMMANDER_SILENT, "laptop#k3x9 silent for 512 ms (command timeout 500 ms)",
                "motors 1-8 set to 0", "robot-pc#q1w2", "laptop#k3x9", "");
        Tuple tuple = Tuple.of(1764000000123L, "CaterpillarRobot", "Motor-Controller", "commander-silent",
                "laptop#k3x9 silent for 512 ms (command timeout 500 ms)", "motors 1-8 set to 0", "robot-pc#q1w2",
                "laptop#k3x9", "");
        assertEquals(tuple, record.toTuple());
        assertEquals(record, StopRecord.parse(tuple));
        for (StopCause cause : StopCause.values()) {
            assertEquals(cause, StopCause.ofWireName(cause.wireName()));
        }
    }

    @Test
    void stopRequestAndAnswer() {
        StopRequest request = new StopRequest("stop-3f2a9c", "ops-laptop (rwe stop)", "end of session",
                List.of("CaterpillarRobot", "DimRoom"), Instant.ofEpochMilli(1764000000123L));
        Tuple tuple = Tuple.of("stop-3f2a9c", "ops-laptop (rwe stop)", "end of session",
                Tuple.of("CaterpillarRobot", "DimRoom"), 1764000000123L);
        assertEquals(tuple, request.toTuple());
        assertEquals(request, StopRequest.parse(tuple));
        StopAnswer answer = new StopAnswer("stop-3f2a9c", "CaterpillarRobot", "Motor-Controller", "robot-pc#q1w2",
                StopAnswer.State.STOPPED, "motors 1-8 set to 0");
        assertEquals(Tuple.of("stop-3f2a9c", "CaterpillarRobot", "Motor-Controller", "robot-pc#q1w2", "stopped",
                "motors 1-8 set to 0"), answer.toTuple());
        assertEquals(answer, StopAnswer.parse(answer.toTuple()));
        assertEquals("no-actuator", StopAnswer.State.NO_ACTUATOR.wireName());
    }
}
