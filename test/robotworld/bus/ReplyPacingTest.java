package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.OptionalLong;
import org.junit.jupiter.api.Test;

/**
 * The baud-rate hint's evidence: replies count as paced at another rate when most answering modules are slow (a
 * mismatch slows them all), not when one or two trickling modules answer among others at the line's pace.
 */
class ReplyPacingTest {

    /** 115200 baud, 10 bits per character. */
    private static final long CHARACTER_NANOS = 86_806;
    /** A byte every 1.04 ms: 9600 baud. */
    private static final long AT_9600 = 1_041_667;

    @Test
    void everyModuleSlowPointsAtTheirRate() {
        ReplyPacing pacing = new ReplyPacing(CHARACTER_NANOS);
        for (int address = 1; address <= 4; address++) {
            for (int frame = 0; frame < 3; frame++) {
                pacing.frameReceived(address, 21, 5, 20 * AT_9600);
            }
        }
        assertEquals(OptionalLong.of(9600), pacing.slowerLineBaud(10));
    }

    @Test
    void stallsThatStretchMostFramesDoNotNameTooSlowARate() {
        ReplyPacing pacing = new ReplyPacing(CHARACTER_NANOS);
        for (int address = 1; address <= 4; address++) {
            pacing.frameReceived(address, 21, 5, 20 * AT_9600);
            for (int frame = 0; frame < 3; frame++) {
                pacing.frameReceived(address, 21, 5, 2 * 20 * AT_9600); // stretched to twice its time by stalls
            }
        }
        assertEquals(OptionalLong.of(9600), pacing.slowerLineBaud(10));
    }

    @Test
    void aFewTricklingModulesAmongCleanOnesAreNoMismatch() {
        ReplyPacing pacing = new ReplyPacing(CHARACTER_NANOS);
        pacing.frameReceived(1, 21, 21, 20 * 1_000_000L); // a byte per ms
        pacing.frameReceived(4, 21, 21, 20 * 2_000_000L); // a byte every 2 ms
        pacing.frameReceived(2, 21, 1, 0); // in one piece: answered, pace unknown
        pacing.frameReceived(3, 21, 4, 20 * CHARACTER_NANOS); // at the line's pace
        assertTrue(pacing.slowerLineBaud(10).isEmpty());
        assertTrue(pacing.medianCharacterNanos(1).getAsLong() >= 2 * CHARACTER_NANOS);
        assertTrue(pacing.medianCharacterNanos(2).isEmpty());
    }

    @Test
    void oneSlowFrameAmongAModulesFastOnesDoesNotMakeItSlow() {
        ReplyPacing pacing = new ReplyPacing(CHARACTER_NANOS);
        for (int frame = 0; frame < 4; frame++) {
            pacing.frameReceived(1, 21, 4, 20 * CHARACTER_NANOS);
        }
        pacing.frameReceived(1, 21, 4, 20 * AT_9600); // a stall on a busy machine
        assertTrue(pacing.slowerLineBaud(10).isEmpty());
    }

    @Test
    void aLoneSlowModuleIsAllTheEvidenceThereIs() {
        ReplyPacing pacing = new ReplyPacing(CHARACTER_NANOS);
        pacing.frameReceived(7, 21, 6, 20 * AT_9600);
        assertEquals(OptionalLong.of(9600), pacing.slowerLineBaud(10));
    }
}
