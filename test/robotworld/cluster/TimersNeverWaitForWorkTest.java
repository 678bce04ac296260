package robotworld.cluster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Removal;
import robotworld.space.Selector;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Timeout;

/**
 * A member's background work calls the cluster (clearing a departed member from every container, reading journals,
 * sweeps), and while the cluster recovers from a failure such a call can block for seconds. The deadlines and the
 * periodic looks of operations that wait without a thread must fire on time all the same. (They shared two threads
 * with that work: after a kill, calls of the kill soak ended past their bound, and a module's provider, whose take
 * had lost its wake-up, waited for its next look for over 5 s.)
 */
@org.junit.jupiter.api.Timeout(120)
class TimersNeverWaitForWorkTest {

    @Test
    void aWaitTimesOutOnTimeWhileBackgroundWorkIsStuck() throws Exception {
        try (LocalCluster cluster = LocalCluster.startPatient(1)) {
            ClusterSpace space = cluster.member(0).openSpace("timers-" + System.nanoTime());
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            CountDownLatch release = new CountDownLatch(1);
            try {
                for (int i = 0; i < 4; i++) {
                    space.node().runInBackground(() -> awaitQuietly(release)); // work stuck in cluster calls
                }
                long started = System.nanoTime();
                CompletableFuture<Object> outcome = takeLater(space, queue, Timeout.ofMillis(300));
                Object result = outcome.get(30, TimeUnit.SECONDS);
                long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
                assertInstanceOf(SpaceTimeoutException.class, result, "it timed out: " + result);
                assertTrue(tookMillis < 2_000, "at its deadline, not when the work ended: " + tookMillis + " ms");
            } finally {
                release.countDown();
            }
        }
    }

    @Test
    void aWaitWhoseWakeUpWasLostFindsItsResultAtItsLookWhileBackgroundWorkIsStuck() throws Exception {
        try (LocalCluster cluster = LocalCluster.startPatient(1)) {
            ClusterSpace space = cluster.member(0).openSpace("looks-" + System.nanoTime());
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            CountDownLatch release = new CountDownLatch(1);
            try {
                CompletableFuture<Object> outcome = takeLater(space, queue, Timeout.ofMillis(60_000));
                assertEquals(1, space.describeContainer(queue).blocked());
                for (int i = 0; i < 4; i++) {
                    space.node().runInBackground(() -> awaitQuietly(release));
                }
                space.node().dropWakeUps = true; // the member that served it died before passing the news on
                space.write(queue, Timeout.TRY_ONCE, Entry.of(1));
                space.node().dropWakeUps = false;
                // its first look comes about a second after it was queued
                assertEquals(List.of(Entry.of(1)), outcome.get(5, TimeUnit.SECONDS));
            } finally {
                release.countDown();
            }
        }
    }

    private static CompletableFuture<Object> takeLater(ClusterSpace space, ContainerRef queue, Timeout timeout) {
        CompletableFuture<Object> outcome = new CompletableFuture<>();
        space.removeLater(queue, Operation.TAKE, timeout, new Selector[] {Selector.fifo(1)}, null,
                robotworld.testsupport.Completions.into(outcome, Removal::entries));
        return outcome;
    }

    private static void awaitQuietly(CountDownLatch latch) {
        try {
            latch.await(60, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
