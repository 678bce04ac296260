package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.time.Duration;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

import robotworld.space.Capi;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/** Notifications: operation filters, the four modes with their timeouts, order, slow listeners, overflow. */
public abstract class NotificationContract extends SpaceContract {

    private Subscription subscribe(ContainerRef ref, Set<Operation> operations, RecordingListener listener) {
        return space.subscribe(ref, operations, NotificationMode.INFINITE, Timeout.INFINITE, listener);
    }

    private static List<Operation> operations(List<Notification> notifications) {
        return notifications.stream().map(Notification::operation).toList();
    }

    @Test
    void writeIsReportedWithItsEntries() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        subscribe(ref, EnumSet.of(Operation.WRITE), listener);
        space.write(ref, Timeout.TRY_ONCE, num(1), num(2));
        Notification notification = listener.awaitCount(1, SOON).get(0);
        assertEquals(ref, notification.container());
        assertEquals(Operation.WRITE, notification.operation());
        assertEquals(nums(1, 2), notification.entries());
        assertEquals(List.of(), notification.displaced());
    }

    @Test
    void onlyTheChosenOperationsAreReported() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        subscribe(ref, EnumSet.of(Operation.TAKE, Operation.DESTROY), listener);
        space.write(ref, Timeout.TRY_ONCE, numArray(1, 2, 3));
        space.read(ref, Timeout.TRY_ONCE);
        space.take(ref, Timeout.TRY_ONCE);
        space.destroy(ref, Timeout.TRY_ONCE, Selector.fifo(2));
        List<Notification> received = listener.awaitCount(2, SOON);
        assertEquals(List.of(Operation.TAKE, Operation.DESTROY), operations(received));
        assertEquals(nums(1), received.get(0).entries());
        assertEquals(nums(2, 3), received.get(1).entries());
    }

    @Test
    void anyReportsEveryOperationInOrderThenTheContainersDestruction() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(2));
        RecordingListener listener = RecordingListener.recording();
        subscribe(ref, Operation.any(), listener);
        space.write(ref, Timeout.TRY_ONCE, num(1));
        space.read(ref, Timeout.TRY_ONCE);
        space.shift(ref, Timeout.TRY_ONCE, num(2), num(3));
        space.take(ref, Timeout.TRY_ONCE);
        space.destroy(ref, Timeout.TRY_ONCE);
        space.destroyContainer(ref);
        List<Notification> received = listener.awaitCount(6, SOON);
        assertEquals(List.of(Operation.WRITE, Operation.READ, Operation.SHIFT, Operation.TAKE, Operation.DESTROY,
                Operation.DESTROY_CONTAINER), operations(received));
        assertEquals(nums(2, 3), received.get(2).entries());
        assertEquals(nums(1), received.get(2).displaced(), "the shift pushed out 1");
        assertEquals(nums(2), received.get(3).entries());
        assertEquals(nums(3), received.get(4).entries());
        for (int i = 1; i < received.size(); i++) {
            assertTrue(received.get(i).sequence() > received.get(i - 1).sequence(), "sequence increases");
        }
        assertEquals(SubscriptionEnd.CONTAINER_DESTROYED, listener.awaitEnd(SOON));
        assertEquals(6, listener.received().size());
    }

    @Test
    void destructionEndsSubscriptionsThatDidNotAskToSeeIt() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        Subscription subscription = subscribe(ref, EnumSet.of(Operation.WRITE), listener);
        space.destroyContainer(ref);
        assertEquals(SubscriptionEnd.CONTAINER_DESTROYED, listener.awaitEnd(SOON));
        assertEquals(List.of(), listener.received());
        assertFalse(subscription.isActive());
    }

    @Test
    void everySubscriberGetsEveryOperation() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener first = RecordingListener.recording();
        RecordingListener second = RecordingListener.recording();
        subscribe(ref, EnumSet.of(Operation.WRITE), first);
        subscribe(ref, EnumSet.of(Operation.WRITE), second);
        for (long i = 0; i < 10; i++) {
            space.write(ref, Timeout.TRY_ONCE, num(i));
        }
        assertEquals(first.awaitCount(10, SOON), second.awaitCount(10, SOON));
    }

    @Test
    void subscriptionsAreCountedWhileActive() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        Subscription subscription = subscribe(ref, Operation.any(), listener);
        assertEquals(1, space.describeContainer(ref).subscriptions());
        assertEquals(ref, subscription.container());
        subscription.cancel();
        listener.awaitEnd(SOON);
        assertEquals(0, space.describeContainer(ref).subscriptions());
    }

    @Test
    void subscribingToAMissingContainerFails() {
        ContainerRef ref = container(Order.FIFO);
        space.destroyContainer(ref);
        assertThrows(ContainerNotFoundException.class,
                () -> subscribe(ref, Operation.any(), RecordingListener.recording()));
        ContainerRef foreign = new ContainerRef(URI.create("embedded:elsewhere"), "c1");
        assertThrows(ContainerNotFoundException.class,
                () -> subscribe(foreign, Operation.any(), RecordingListener.recording()));
    }

    // ---- modes ----

    @Test
    void onceFiresForTheFirstMatchingOperationOnly() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        Subscription subscription = space.subscribe(ref, EnumSet.of(Operation.TAKE), NotificationMode.ONCE,
                Timeout.INFINITE, listener);
        space.write(ref, Timeout.TRY_ONCE, numArray(1, 2, 3));
        space.take(ref, Timeout.TRY_ONCE);
        space.take(ref, Timeout.TRY_ONCE);
        assertEquals(SubscriptionEnd.FIRED_ONCE, listener.awaitEnd(SOON));
        assertEquals(1, listener.received().size());
        assertEquals(nums(1), listener.received().get(0).entries());
        assertFalse(subscription.isActive());
    }

    @Test
    void onceExpiresWhenNothingHappensInTime() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        space.subscribe(ref, Operation.any(), NotificationMode.ONCE, Timeout.ofMillis(100), listener);
        assertEquals(SubscriptionEnd.EXPIRED, listener.awaitEnd(SOON));
        space.write(ref, Timeout.TRY_ONCE, num(1));
        assertEquals(List.of(), listener.received());
    }

    @Test
    void restrictedFiresUntilItsTimeoutEvenWhileBusy() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        long start = System.nanoTime();
        // a timeout of 100 writing periods: a busy machine that holds the writer or the delivery up for a while
        // still lets several writes fire before it
        space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.RESTRICTED, Timeout.ofMillis(2_000),
                listener);
        long written = writeEvery(ref, 20, () -> listener.endReason() != null);
        long lasted = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertEquals(SubscriptionEnd.EXPIRED, listener.awaitEnd(SOON));
        assertTrue(lasted >= 1_990, "ended after " + lasted + " ms");
        assertTrue(listener.received().size() >= 2, "fired repeatedly");
        assertTrue(listener.received().size() <= written);
    }

    @Test
    void prolongStaysAliveWhileItFiresAndExpiresAfterAQuietTimeout() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        // a timeout 75 times the writing period: a busy machine that holds the writer or the delivery up for a
        // while (a loaded cluster took over a second) cannot make the subscription expire between two writes
        Subscription subscription = space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.PROLONG,
                Timeout.ofMillis(3_000), listener);
        long start = System.nanoTime();
        // keep it busy for one and a half times its timeout: it must survive
        long written = writeEvery(ref, 40, () -> System.nanoTime() - start > TimeUnit.MILLISECONDS.toNanos(4_500));
        assertTrue(subscription.isActive(), "prolong expired although it kept firing");
        assertEquals(SubscriptionEnd.EXPIRED, listener.awaitEnd(SOON));
        long ended = System.nanoTime();
        // the quiet timeout runs from its last firing, which began no earlier than the write it reports: the last
        // write's, unless a notification that arrives late finds the timeout already run out (a cluster measures
        // timeouts as notifications arrive at the member that has the subscription)
        List<Notification> fired = listener.received();
        Entry lastFired = fired.get(fired.size() - 1).entries().get(0);
        int write = writeStarts.size() - 1;
        while (!Entry.of((long) write).equals(lastFired)) {
            write--;
        }
        long quiet = TimeUnit.NANOSECONDS.toMillis(ended - writeStarts.get(write));
        assertTrue(quiet >= 2_990, "expired " + quiet + " ms after the write of its last notification began ("
                + fired.size() + " notifications for " + written + " writes)");
    }

    @Test
    void infiniteIgnoresItsTimeoutAndLastsUntilCancelled() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        Subscription subscription = space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE,
                Timeout.ofMillis(50), listener);
        long start = System.nanoTime();
        eventually("200 ms passed", () -> System.nanoTime() - start > TimeUnit.MILLISECONDS.toNanos(200));
        space.write(ref, Timeout.TRY_ONCE, num(1));
        listener.awaitCount(1, SOON);
        assertTrue(subscription.isActive());
        subscription.cancel();
        subscription.cancel(); // harmless
        space.write(ref, Timeout.TRY_ONCE, num(2));
        assertEquals(SubscriptionEnd.CANCELLED, listener.awaitEnd(SOON));
        assertEquals(1, listener.received().size());
        assertEquals(1, listener.endCalls());
    }

    @Test
    void cancelStillDeliversWhatHappenedBefore() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.gated();
        Subscription subscription = subscribe(ref, EnumSet.of(Operation.WRITE), listener);
        for (long i = 1; i <= 3; i++) {
            space.write(ref, Timeout.TRY_ONCE, num(i));
        }
        subscription.cancel();
        space.write(ref, Timeout.TRY_ONCE, num(4));
        listener.open();
        assertEquals(SubscriptionEnd.CANCELLED, listener.awaitEnd(SOON));
        assertEquals(List.of(nums(1), nums(2), nums(3)),
                listener.received().stream().map(Notification::entries).toList());
    }

    @Test
    void closingTheSpaceEndsSubscriptions() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        subscribe(ref, Operation.any(), listener);
        space.close();
        assertEquals(SubscriptionEnd.SPACE_CLOSED, listener.awaitEnd(SOON));
    }

    // ---- slow listeners ----

    @Test
    void aSlowListenerNeverBlocksOperations() {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener slow = RecordingListener.gated();
        subscribe(ref, EnumSet.of(Operation.WRITE), slow);
        int operations = 1_000;
        long start = System.nanoTime();
        for (long i = 0; i < operations; i++) {
            space.write(ref, Timeout.TRY_ONCE, num(i));
            space.take(ref, Timeout.TRY_ONCE);
        }
        assertTrue(System.nanoTime() - start < SOON.toNanos(), "operations were held up by the listener");
        slow.open();
        List<Notification> received = slow.awaitCount(operations, SOON);
        for (int i = 0; i < operations; i++) {
            assertEquals(nums(i), received.get(i).entries(), "in operation order");
        }
    }

    @Test
    void aFailingListenerKeepsReceiving() {
        ContainerRef ref = container(Order.FIFO);
        AtomicInteger calls = new AtomicInteger();
        RecordingListener after = RecordingListener.recording();
        space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE, Timeout.INFINITE,
                new NotificationListener() {
                    @Override
                    public void onNotification(Notification notification) {
                        if (calls.incrementAndGet() == 1) {
                            throw new IllegalStateException("listener bug (expected by the test)");
                        }
                        after.onNotification(notification);
                    }
                });
        space.write(ref, Timeout.TRY_ONCE, num(1));
        space.write(ref, Timeout.TRY_ONCE, num(2));
        assertEquals(nums(2), after.awaitCount(1, SOON).get(0).entries());
    }

    @Test
    void overflowEndsTheSubscriptionAfterAnUnbrokenPrefix() {
        int queue = 5;
        try (Capi small = newSpace(queue)) {
            ContainerRef ref = small.createContainer(ContainerSpec.of(Order.FIFO));
            RecordingListener slow = RecordingListener.gated();
            Subscription subscription = small.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE,
                    Timeout.INFINITE, slow);
            int writes = 50;
            for (long i = 1; i <= writes; i++) {
                small.write(ref, Timeout.TRY_ONCE, num(i)); // never blocked by the stuck listener
            }
            eventually("the subscription overflowed", () -> !subscription.isActive());
            slow.open();
            assertEquals(SubscriptionEnd.OVERFLOWED, slow.awaitEnd(SOON));
            List<Notification> received = slow.received();
            assertTrue(received.size() >= queue && received.size() < writes, "delivered " + received.size());
            for (int i = 0; i < received.size(); i++) {
                assertEquals(nums(i + 1), received.get(i).entries(), "no gap before the overflow");
            }
            small.write(ref, Timeout.TRY_ONCE, num(99));
            assertEquals(received.size(), slow.received().size(), "nothing after the overflow");
        }
    }

    /** When {@link #writeEvery} last began a write: no event of it can be older. */
    /** When each write of {@link #writeEvery} began, by the number it wrote. */
    private final List<Long> writeStarts = new java.util.ArrayList<>();

    /** Writes one entry every {@code periodMillis} until {@code stop} holds (at most {@link #SOON}); returns the count. */
    private long writeEvery(ContainerRef ref, long periodMillis, java.util.function.BooleanSupplier stop) {
        long count = 0;
        writeStarts.clear();
        long deadline = System.nanoTime() + SOON.toNanos();
        while (!stop.getAsBoolean() && System.nanoTime() < deadline) {
            writeStarts.add(System.nanoTime());
            space.write(ref, Timeout.TRY_ONCE, Entry.of(count++));
            sleep(Duration.ofMillis(periodMillis));
        }
        return count;
    }

    private static void sleep(Duration duration) {
        try {
            Thread.sleep(duration.toMillis());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }
}
