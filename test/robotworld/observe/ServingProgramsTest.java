package robotworld.observe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.time.Instant;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import robotworld.safety.Heartbeat;

/**
 * The verdicts on heartbeats, with this computer's clock given by hand (nanoseconds): what a monitor concludes
 * from programs found at the start, beating, falling silent, ending, and taking over from each other.
 */
class ServingProgramsTest {

    private static final long MS = 1_000_000L;
    private static final Heartbeat.ModuleName MOTOR = new Heartbeat.ModuleName("Robot", "Motor");
    private static final Heartbeat.ModuleName BUMPER = new Heartbeat.ModuleName("Robot", "Bumper");

    private final ServingPrograms programs = new ServingPrograms(Set.of("Robot", "Room"));

    @Test
    void aProgramFoundAtTheStartMustBeatItIsSilentOtherwise() {
        programs.heard(beat("old-pc#1", 7, false, MOTOR), Instant.EPOCH, 0, false);
        assertNull(programs.verdict("Robot", 500 * MS), "not yet known: it may beat any moment");
        ServingPrograms.Verdict silent = programs.verdict("Robot", 1_001 * MS);
        assertEquals(Liveness.State.SILENT, silent.state());
        assertEquals("no heartbeat from old-pc#1 since watching began", silent.basis());
        assertNull(silent.lastSign(), "when it last beat is unknown");
    }

    @Test
    void aBeatingProgramIsAliveUntilItsHeartbeatsStopForASecond() {
        for (int i = 1; i <= 10; i++) {
            programs.heard(beat("robot-pc#1", i, false, MOTOR, BUMPER), Instant.EPOCH, i * 100 * MS, true);
        }
        assertEquals(Liveness.State.ALIVE, programs.verdict("Robot", 1_900 * MS).state());
        assertEquals("heartbeats of robot-pc#1", programs.verdict("Robot", 1_900 * MS).basis());
        ServingPrograms.Verdict silent = programs.verdict("Robot", 2_001 * MS);
        assertEquals(Liveness.State.SILENT, silent.state());
        assertEquals("no heartbeat from robot-pc#1 for 1.0 s", silent.basis());
        assertNull(programs.verdict("Room", 2_001 * MS), "no heartbeat names the room");
    }

    @Test
    void theSameHeartbeatReadAgainIsNoSignOfLife() {
        programs.heard(beat("robot-pc#1", 5, false, MOTOR), Instant.EPOCH, 0, true);
        programs.heard(beat("robot-pc#1", 5, false, MOTOR), Instant.EPOCH, 900 * MS, true);
        assertEquals(Liveness.State.SILENT, programs.verdict("Robot", 1_001 * MS).state());
    }

    @Test
    void slowHeartbeatsAreGivenFivePeriods() {
        programs.heard(beat("robot-pc#1", 1, false, 500, MOTOR), Instant.EPOCH, 0, true);
        assertEquals(Liveness.State.ALIVE, programs.verdict("Robot", 2_400 * MS).state());
        assertEquals(Liveness.State.SILENT, programs.verdict("Robot", 2_600 * MS).state());
    }

    @Test
    void aClosedProgramHasEndedThoughItsLastHeartbeatNamesNoActuatorAnyMore() {
        programs.heard(beat("room-pc#1", 1, false, new Heartbeat.ModuleName("Room", "Fan")), Instant.EPOCH, 0, true);
        programs.heard(beat("room-pc#1", 2, true), Instant.EPOCH, 100 * MS, true);
        ServingPrograms.Verdict ended = programs.verdict("Room", 60_000 * MS);
        assertEquals(Liveness.State.ENDED, ended.state());
        assertEquals("room-pc#1 ended", ended.basis());
    }

    @Test
    void anOlderHeartbeatArrivingAfterTheLastDoesNotUndoTheEnd() {
        programs.heard(beat("room-pc#1", 1, false, new Heartbeat.ModuleName("Room", "Fan")), Instant.EPOCH, 0, true);
        programs.heard(beat("room-pc#1", 3, true), Instant.EPOCH, 100 * MS, true);
        programs.heard(beat("room-pc#1", 2, false, new Heartbeat.ModuleName("Room", "Fan")), Instant.EPOCH, 110 * MS,
                true); // sent before the last one, delivered after it
        assertEquals(Liveness.State.ENDED, programs.verdict("Room", 60_000 * MS).state());
    }

    @Test
    void aProgramRestartedUnderANewIdTakesOverFromTheDeadOne() {
        programs.heard(beat("robot-pc#1", 1, false, MOTOR, BUMPER), Instant.EPOCH, 0, true);
        assertEquals(Liveness.State.SILENT, programs.verdict("Robot", 3_000 * MS).state());
        programs.heard(beat("robot-pc#2", 1, false, MOTOR, BUMPER), Instant.EPOCH, 3_000 * MS, true);
        assertEquals(Liveness.State.ALIVE, programs.verdict("Robot", 3_100 * MS).state());
        assertEquals("heartbeats of robot-pc#2", programs.verdict("Robot", 3_100 * MS).basis());
    }

    @Test
    void aModuleWhoseOwnProgramIsSilentMakesItsParticipantSilentThoughAnotherBeats() {
        programs.heard(beat("robot-pc#1", 1, false, MOTOR), Instant.EPOCH, 0, true);
        for (int i = 1; i <= 30; i++) {
            programs.heard(beat("arm-pc#1", i, false, BUMPER), Instant.EPOCH, i * 100 * MS, true);
        }
        assertEquals("no heartbeat from robot-pc#1 for 3.0 s", programs.verdict("Robot", 3_000 * MS).basis());
    }

    @Test
    void programsThatOnlyCommandOrServeOtherWorldsAreIgnored() {
        programs.heard(beat("laptop#1", 1, false), Instant.EPOCH, 0, true);
        programs.heard(beat("lab-pc#1", 1, false, new Heartbeat.ModuleName("OtherBot", "Motor")), Instant.EPOCH, 0,
                true);
        assertNull(programs.verdict("Robot", 5_000 * MS));
    }

    private static Heartbeat beat(String id, long sequence, boolean ended, Heartbeat.ModuleName... serves) {
        return beat(id, sequence, ended, 100, serves);
    }

    private static Heartbeat beat(String id, long sequence, boolean ended, long periodMillis,
            Heartbeat.ModuleName... serves) {
        return new Heartbeat(id, id.substring(0, id.indexOf('#')), List.of(serves), ended, sequence, periodMillis,
                0);
    }
}
