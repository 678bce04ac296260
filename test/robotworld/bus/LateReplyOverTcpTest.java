package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.Test;

/**
 * A reply that comes after its request timed out must never be taken for the reply to the next request to the same
 * module, even when function code and length match: reading one bumper and reading all eight both answer
 * {@code 02 01 xx}. Found as a wrong bumper mask in an integration test on a loaded machine.
 */
class LateReplyOverTcpTest {

    /** Bumpers 4 and 6, the front ones, closed: the robot starts touching the wall at x = 2000. */
    private static final int FRONT_BUMPERS = 1 << 3 | 1 << 5;

    @Test
    void aReplyAfterItsTimeoutIsNeverTakenForTheNextCallsAnswer() throws Exception {
        String atTheWall = BusRig.FOUR_MODULES.replace("<Body x=\"500\"", "<Body x=\"1850\"");
        // a 500 ms timeout with one attempt (late-reply window 2 s) and a module that answers 1.2 s late: the late
        // reply comes while the next call waits out the window, and a busy machine has room to be slow in both
        BusTiming timing = BusRig.TIMING.withResponseTimeout(Duration.ofMillis(500)).withAttempts(1);
        try (BusRig rig = BusRig.tcp(atTheWall, timing)) {
            BumperModuleProxy bumper = new BumperModuleProxy(rig.bus(), 2, "Bumper-Sensor");
            assertEquals(FRONT_BUMPERS, onceAnswered(bumper));

            rig.robot().faults(2).replyDelay(Duration.ofMillis(1_200));
            assertThrows(BusTimeoutException.class, () -> bumper.getSingleBumper(4)); // its 02 01 01 comes late
            Thread.sleep(400); // the late reply is due about 300 ms into the next call
            try {
                assertEquals(FRONT_BUMPERS, bumper.getAllBumper(), "never the late single-bumper reply (1)");
            } catch (BusTimeoutException stillSlow) {
                // a clean timeout is right too: the module is still slower than the timeout
            }

            rig.robot().faults(2).replyDelay(Duration.ZERO);
            assertEquals(FRONT_BUMPERS, onceAnswered(bumper), "once the module is quick again");
            assertEquals(FRONT_BUMPERS, onceAnswered(bumper));
            BusStatistics statistics = rig.bus().statistics();
            assertTrue(statistics.staleReplies() >= 1, "late replies are counted as stale: " + statistics);
            assertEquals(0, statistics.strayFrames(), statistics.toString());
        }
    }

    /**
     * All bumpers, asked again if the answer missed its 500 ms timeout: a quick module on a very busy machine may
     * (one attempt per call here); every answer that does come is checked.
     */
    private static int onceAnswered(BumperModuleProxy bumper) {
        long giveUp = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        while (true) {
            try {
                return bumper.getAllBumper();
            } catch (BusTimeoutException late) {
                if (System.nanoTime() - giveUp > 0) {
                    throw late;
                }
            }
        }
    }
}
