package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Which server a client of several moves on to when its server fails. */
class ServerRotationTest {

    private static final long SECOND = 1_000_000_000L;
    private static final long SUSPECT = ServerRotation.SUSPECT_NANOS;
    private static final boolean DOWN = true;
    private static final boolean ANSWERED = false;

    @Test
    void startsWithTheFirstAndMovesOnInTheOrderGiven() {
        ServerRotation rotation = new ServerRotation(3);
        assertEquals(0, rotation.current());
        assertEquals(1, rotation.failed(SECOND, DOWN));
        assertEquals(2, rotation.failed(2 * SECOND, DOWN));
        assertEquals(2, rotation.current());
    }

    /** The pattern seen when a cluster member is killed: its neighbour in the list has a moment's trouble. */
    @Test
    void aServerKnownToBeDownIsNotTriedAgainBeforeOneThatOnlyHadTrouble() {
        ServerRotation rotation = new ServerRotation(3);
        long t = 5 * SECOND;
        assertEquals(1, rotation.failed(t, ANSWERED)); // 0 could not complete a call
        assertEquals(2, rotation.failed(t + 10, DOWN)); // 1 is down
        assertEquals(0, rotation.failed(t + 20, ANSWERED)); // 2 had trouble too: 0 answered, 1 did not
        // 0 has trouble again: 1 comes next in the list, but it is down; 2 answered
        assertEquals(2, rotation.failed(t + 30, ANSWERED));
        assertEquals(0, rotation.failed(t + 40, ANSWERED));
    }

    @Test
    void aFreshServerIsPreferredToOnesThatFailedLately() {
        ServerRotation rotation = new ServerRotation(4);
        long t = 3 * SECOND;
        rotation.failed(t, DOWN); // 0 → 1
        rotation.failed(t + SUSPECT / 2, DOWN); // 1 → 2
        rotation.failed(t + SUSPECT / 2 + 10, DOWN); // 2 → 3
        // 0's failure is now older than the suspect period, 1's and 2's are not: from 3, the next is 0
        assertEquals(0, rotation.failed(t + SUSPECT + 1, ANSWERED));
        // 0 fails: 1 and 2 are suspect, 3 answered a moment ago: 3 is the better bet
        assertEquals(3, rotation.failed(t + SUSPECT + 2, DOWN));
        // once 1's failure is older than the suspect period, 3's trouble moves the client past 0 (down lately) to 1
        assertEquals(1, rotation.failed(t + SUSPECT / 2 + SUSPECT + 1, ANSWERED));
    }

    @Test
    void whenAllFailedTheOldestFailureIsTriedFirst() {
        ServerRotation rotation = new ServerRotation(3);
        long t = SECOND;
        rotation.failed(t, DOWN); // 0 → 1
        rotation.failed(t + 10, DOWN); // 1 → 2
        assertEquals(0, rotation.failed(t + 20, DOWN)); // 2 → 0 (older than 1's)
        assertEquals(1, rotation.failed(t + 30, DOWN)); // 0 → 1 (older than 2's)
    }

    @Test
    void withOneServerThereIsNowhereElse() {
        ServerRotation rotation = new ServerRotation(1);
        assertEquals(0, rotation.failed(SECOND, DOWN));
    }

    @Test
    void aClientGoesHomeOnlyAfterTheFirstServersFailureIsOld() {
        ServerRotation rotation = new ServerRotation(3);
        assertFalse(rotation.mayGoHome(SECOND), "at home already");
        long t = 5 * SECOND;
        assertEquals(1, rotation.failed(t, DOWN));
        assertFalse(rotation.mayGoHome(t + SUSPECT / 2), "its failure is recent");
        assertTrue(rotation.mayGoHome(t + SUSPECT + 1));
        rotation.homeFailed(t + SUSPECT + 1); // checked: still not serving
        assertFalse(rotation.mayGoHome(t + SUSPECT + 2), "passed over again after a failed check");
        assertTrue(rotation.mayGoHome(t + 2 * SUSPECT + 2));
        assertEquals(0, rotation.wentHome());
        assertEquals(0, rotation.current());
        assertFalse(rotation.mayGoHome(t + 3 * SUSPECT));
    }

    @Test
    void aClientThatStartedElsewhereMayGoHomeAtOnce() {
        ServerRotation rotation = new ServerRotation(2);
        assertEquals(1, rotation.failed(SECOND, ANSWERED));
        // the first server answered but could not serve; it had failed, so it waits like any other
        assertFalse(rotation.mayGoHome(SECOND + 1));
        assertTrue(rotation.mayGoHome(SECOND + SUSPECT + 1));
    }
}
