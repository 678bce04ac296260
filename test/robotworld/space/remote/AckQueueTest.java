package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Take confirmations: carried by requests when they come, sent alone after the delay when they do not. */
class AckQueueTest {

    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);

    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
    private final List<String> sentAlone = new CopyOnWriteArrayList<>();

    @AfterEach
    void stopTimer() {
        timer.shutdownNow();
    }

    @Test
    void aConfirmationNoRequestTakesIsSentAloneOnceItHasWaitedTheDelay() throws Exception {
        AckQueue acks = new AckQueue(timer, 20_000, sentAlone::add, new AckSweeper(false));
        acks.add("c1");
        assertTrue(acks.sweep(0), "outstanding");
        assertTrue(acks.sweep(19 * MS));
        settle();
        assertEquals(List.of(), sentAlone, "not before the delay");
        acks.sweep(20 * MS);
        settle();
        assertEquals(List.of("c1"), sentAlone);
        assertFalse(acks.sweep(25 * MS), "nothing outstanding once sent");
    }

    @Test
    void confirmationsThatRequestsKeepTakingAreNeverSentAlone() throws Exception {
        AckQueue acks = new AckQueue(timer, 20_000, sentAlone::add, new AckSweeper(false));
        long now = 0;
        for (int call = 0; call < 100; call++) {
            acks.add("c" + call);
            acks.sweep(now);
            now += 15 * MS; // a request every 15 ms, each taking what is waiting
            assertEquals("c" + call, acks.drain());
            acks.add("d" + call); // the next confirmation is already waiting when the sweeper looks again
            acks.sweep(now);
            now += 15 * MS;
            assertEquals("d" + call, acks.drain());
        }
        settle();
        assertEquals(List.of(), sentAlone);
    }

    @Test
    void theCountStartsAgainWhenARequestTookSomeOfTheWaitingOnes() throws Exception {
        AckQueue acks = new AckQueue(timer, 20_000, sentAlone::add, new AckSweeper(false));
        acks.add("a");
        acks.sweep(0);
        acks.drain();
        acks.add("b");
        acks.sweep(20 * MS); // a request went since the last look: b is counted from here
        acks.sweep(30 * MS);
        settle();
        assertEquals(List.of(), sentAlone);
        acks.sweep(40 * MS);
        settle();
        assertEquals(List.of("b"), sentAlone);
    }

    @Test
    void theSharedSweeperSendsAWaitingConfirmationAloneButNotBeforeTheDelay() throws Exception {
        AckQueue acks = new AckQueue(timer, 20_000, sentAlone::add);
        try {
            long start = System.nanoTime();
            acks.add("c1");
            while (sentAlone.isEmpty() && System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5)) {
                Thread.sleep(1);
            }
            long waited = System.nanoTime() - start;
            assertEquals(List.of("c1"), sentAlone);
            assertTrue(waited >= 20 * MS, "not before the delay: " + waited / MS + " ms");
            assertNull(acks.drain());
        } finally {
            acks.close();
        }
    }

    @Test
    void aSweeperParkedAfterAQuietSecondWakesForTheNextConfirmation() throws Exception {
        AckQueue acks = new AckQueue(timer, 20_000, sentAlone::add, new AckSweeper(true));
        try {
            acks.add("c1");
            awaitSent(1);
            Thread.sleep(1_500); // a second without confirmations: the sweeper parks for good
            acks.add("c2");
            awaitSent(2); // within 5 s: only if the confirmation woke the sweeper
            assertEquals(List.of("c1", "c2"), sentAlone);
        } finally {
            acks.close();
        }
    }

    private void awaitSent(int count) throws InterruptedException {
        long start = System.nanoTime();
        while (sentAlone.size() < count && System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5)) {
            Thread.sleep(1);
        }
        assertEquals(count, sentAlone.size(), "sent alone in time");
    }

    @Test
    void withoutADelayAConfirmationIsSentAtOnce() throws Exception {
        AckQueue acks = new AckQueue(timer, 0, sentAlone::add, new AckSweeper(false));
        acks.add("c1");
        long start = System.nanoTime();
        while (sentAlone.isEmpty() && System.nanoTime() - start < TimeUnit.SECONDS.toNanos(5)) {
            Thread.sleep(1);
        }
        assertEquals(List.of("c1"), sentAlone);
    }

    /** Lets the timer run what a sweep handed it. */
    private void settle() throws Exception {
        timer.submit(() -> { }).get(5, TimeUnit.SECONDS);
    }
}
