package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import robotworld.space.ContainerDestroyedException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.InvalidOperationException;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Template;
import robotworld.space.Timeout;

/** Timeouts, the blocking rules of every operation, shift's displacement, fairness and wake-ups on destruction. */
public abstract class BlockingContract extends SpaceContract {

    // ---- timeouts ----

    @Test
    void tryOnceFailsAtOnceWithATimeout() {
        ContainerRef ref = container(Order.FIFO);
        long start = System.nanoTime();
        assertThrows(SpaceTimeoutException.class, () -> space.take(ref, Timeout.TRY_ONCE));
        // "at once" as opposed to waiting: generous, since a busy machine may hold any call up for a while
        assertTrue(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start) < SOON.toMillis() / 4);
        assertEquals(0, space.describeContainer(ref).blocked());
    }

    @Test
    void timedWaitFailsAfterTheTimeout() {
        ContainerRef ref = container(Order.FIFO);
        long start = System.nanoTime();
        assertThrows(SpaceTimeoutException.class, () -> space.read(ref, Timeout.ofMillis(150)));
        long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertTrue(waited >= 140, "gave up after only " + waited + " ms");
        assertTrue(waited < SOON.toMillis(), "waited " + waited + " ms");
        assertEquals(0, space.describeContainer(ref).blocked(), "a timed-out operation leaves no trace");
    }

    @Test
    void timedWaitSucceedsWhenTheEntryComesInTime() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        Future<List<Entry>> taker = async(() -> space.take(ref, Timeout.ofMillis(SOON.toMillis())));
        awaitBlocked(ref, 1);
        space.write(ref, Timeout.TRY_ONCE, num(1));
        assertEquals(nums(1), result(taker));
    }

    @Test
    void infiniteWaitSucceedsWhenTheEntryComes() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        Future<List<Entry>> taker = async(() -> space.take(ref, Timeout.INFINITE, Selector.fifo(2)));
        awaitBlocked(ref, 1);
        space.write(ref, Timeout.TRY_ONCE, num(1));
        assertFalse(taker.isDone());
        space.write(ref, Timeout.TRY_ONCE, num(2));
        assertEquals(nums(1, 2), result(taker));
        assertSize(ref, 0);
    }

    // ---- write blocking ----

    @Test
    void writeWaitsWhileTheContainerIsFull() throws Exception {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(2));
        space.write(ref, Timeout.TRY_ONCE, num(1), num(2));
        assertThrows(SpaceTimeoutException.class, () -> space.write(ref, Timeout.TRY_ONCE, num(3)));
        Future<?> writer = async(() -> {
            space.write(ref, Timeout.INFINITE, num(3));
            return null;
        });
        awaitBlocked(ref, 1);
        assertEquals(nums(1), space.take(ref, Timeout.TRY_ONCE));
        result(writer);
        assertEquals(nums(2, 3), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(2)));
    }

    @Test
    void multiEntryWriteIsAllOrNothing() throws Exception {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(3));
        space.write(ref, Timeout.TRY_ONCE, num(1), num(2));
        Future<?> writer = async(() -> {
            space.write(ref, Timeout.INFINITE, num(3), num(4));
            return null;
        });
        awaitBlocked(ref, 1);
        assertSize(ref, 2); // nothing of the blocked write is visible
        space.take(ref, Timeout.TRY_ONCE);
        result(writer);
        assertEquals(nums(2, 3, 4), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(3)));
    }

    @Test
    void writeOfMoreEntriesThanTheCapacityIsRejected() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(2));
        assertThrows(InvalidOperationException.class, () -> space.write(ref, Timeout.INFINITE, numArray(1, 2, 3)));
    }

    @Test
    void setWaitsWhileAnEqualEntryIsPresent() throws Exception {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).set());
        space.write(ref, Timeout.TRY_ONCE, num(1), num(2));
        assertThrows(SpaceTimeoutException.class, () -> space.write(ref, Timeout.TRY_ONCE, num(1)));
        Future<?> writer = async(() -> {
            space.write(ref, Timeout.INFINITE, num(1));
            return null;
        });
        awaitBlocked(ref, 1);
        space.take(ref, Timeout.TRY_ONCE); // takes 1
        result(writer);
        assertEquals(nums(2, 1), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(2)));
        assertThrows(InvalidOperationException.class, () -> space.write(ref, Timeout.TRY_ONCE, num(5), num(5)));
    }

    @Test
    void bagAllowsDuplicates() {
        ContainerRef ref = container(Order.FIFO);
        space.write(ref, Timeout.TRY_ONCE, num(1), num(1));
        space.write(ref, Timeout.TRY_ONCE, num(1));
        assertSize(ref, 3);
    }

    // ---- shift ----

    @ParameterizedTest
    @EnumSource(value = Order.class, names = {"FIFO", "LIFO", "LRU"})
    void shiftIntoAFullContainerDisplacesWhatTheBaseOrderTakesNext(Order order) {
        ContainerRef ref = container(ContainerSpec.of(order).bounded(3));
        for (long value = 1; value <= 3; value++) {
            space.write(ref, Timeout.TRY_ONCE, num(value));
        }
        if (order == Order.LRU) {
            space.read(ref, Timeout.TRY_ONCE); // uses 1, so 2 is now least recently used
        }
        List<Entry> displaced = space.shift(ref, Timeout.TRY_ONCE, num(4));
        List<Entry> expected = switch (order) {
            case FIFO -> nums(1);
            case LIFO -> nums(3);
            default -> nums(2);
        };
        assertEquals(expected, displaced);
        assertSize(ref, 3);
        assertTrue(space.read(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL)).contains(num(4)));
    }

    @Test
    void shiftIntoAFullRandomContainerDisplacesOneEntry() {
        ContainerRef ref = container(ContainerSpec.of(Order.RANDOM).bounded(3));
        space.write(ref, Timeout.TRY_ONCE, numArray(1, 2, 3));
        List<Entry> displaced = space.shift(ref, Timeout.TRY_ONCE, num(4));
        assertEquals(1, displaced.size());
        assertTrue(nums(1, 2, 3).contains(displaced.get(0)));
        List<Entry> left = space.read(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL));
        assertTrue(left.contains(num(4)));
        assertFalse(left.contains(displaced.get(0)));
    }

    @Test
    void shiftWithRoomIsAPlainWrite() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(3));
        assertEquals(List.of(), space.shift(ref, Timeout.TRY_ONCE, num(1), num(2)));
        assertEquals(nums(1, 2), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(2)));
    }

    @Test
    void shiftOfMoreEntriesThanTheCapacityKeepsTheLastOnes() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(2));
        assertEquals(nums(1, 2), space.shift(ref, Timeout.TRY_ONCE, numArray(1, 2, 3, 4)));
        assertEquals(nums(3, 4), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(2)));
    }

    @Test
    void shiftReplacesTheEntryUnderTheSameKey() {
        ContainerRef ref = container(ContainerSpec.of(Order.LIFO).withKeyView());
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("host", num(1)), Item.keyed("other", num(5))));
        assertEquals(nums(1), space.shift(ref, Timeout.TRY_ONCE, List.of(Item.keyed("host", num(2)))));
        assertEquals(nums(2), space.read(ref, Timeout.TRY_ONCE, Selector.key("host")));
        assertSize(ref, 2);
    }

    @Test
    void shiftReplacesTheEntryAtTheSamePosition() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).withVectorView());
        space.write(ref, Timeout.TRY_ONCE, numArray(10, 11));
        assertEquals(nums(11), space.shift(ref, Timeout.TRY_ONCE, List.of(Item.at(1, num(21)))));
        assertEquals(nums(10, 21), space.read(ref, Timeout.TRY_ONCE, Selector.vector(0, 2)));
    }

    @Test
    void shiftReplacesAnEqualEntryInASet() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).set());
        space.write(ref, Timeout.TRY_ONCE, num(1), num(2));
        assertEquals(nums(1), space.shift(ref, Timeout.TRY_ONCE, num(1)));
        assertEquals(nums(2, 1), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(2)), "the shifted 1 is now newest");
    }

    @Test
    void shiftServesWaitingOperations() throws Exception {
        ContainerRef ref = container(ContainerSpec.of(Order.LIFO).withKeyView());
        Future<List<Entry>> caller = async(() -> space.take(ref, Timeout.INFINITE, Selector.key("robot1")));
        awaitBlocked(ref, 1);
        space.shift(ref, Timeout.TRY_ONCE, List.of(Item.keyed("robot1", Entry.of("done"))));
        assertEquals(List.of(Entry.of("done")), result(caller));
    }

    // ---- destroy (entries) ----

    @Test
    void destroyWaitsLikeTakeAndReportsTheCount() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        Future<Integer> destroyer = async(() -> space.destroy(ref, Timeout.INFINITE, Selector.fifo(2)));
        awaitBlocked(ref, 1);
        space.write(ref, Timeout.TRY_ONCE, numArray(1, 2, 3));
        assertEquals(2, result(destroyer));
        assertEquals(nums(3), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL)));
    }

    // ---- fairness ----

    @Test
    void blockedTakesAreServedOldestFirst() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        List<Future<List<Entry>>> takers = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            takers.add(async(() -> space.take(ref, Timeout.INFINITE)));
            awaitBlocked(ref, i + 1);
        }
        for (long value = 1; value <= 3; value++) {
            space.write(ref, Timeout.TRY_ONCE, num(value));
        }
        for (int i = 0; i < 3; i++) {
            assertEquals(nums(i + 1), result(takers.get(i)), "taker " + i);
        }
    }

    @Test
    void blockedWritesAreServedOldestFirst() throws Exception {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(1));
        space.write(ref, Timeout.TRY_ONCE, num(0));
        List<Future<?>> writers = new ArrayList<>();
        for (int i = 1; i <= 3; i++) {
            long value = i * 10;
            writers.add(async(() -> {
                space.write(ref, Timeout.INFINITE, num(value));
                return null;
            }));
            awaitBlocked(ref, i);
        }
        List<Entry> taken = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            taken.addAll(space.take(ref, Timeout.ofMillis(SOON.toMillis())));
        }
        assertEquals(nums(0, 10, 20, 30), taken);
        for (Future<?> writer : writers) {
            result(writer);
        }
    }

    @Test
    void aWaiterThatCannotBeServedDoesNotHoldBackYoungerOnes() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        Future<List<Entry>> wantsThree = async(() -> space.take(ref, Timeout.INFINITE, Selector.fifo(3)));
        awaitBlocked(ref, 1);
        Future<List<Entry>> wantsOne = async(() -> space.take(ref, Timeout.INFINITE));
        awaitBlocked(ref, 2);
        space.write(ref, Timeout.TRY_ONCE, num(1));
        assertEquals(nums(1), result(wantsOne));
        assertFalse(wantsThree.isDone());
        space.write(ref, Timeout.TRY_ONCE, numArray(2, 3, 4));
        assertEquals(nums(2, 3, 4), result(wantsThree));
    }

    @Test
    void olderBlockedReadsSeeTheEntryBeforeAYoungerTakeRemovesIt() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        Future<List<Entry>> reader1 = async(() -> space.read(ref, Timeout.INFINITE));
        awaitBlocked(ref, 1);
        Future<List<Entry>> reader2 = async(() -> space.read(ref, Timeout.INFINITE));
        awaitBlocked(ref, 2);
        Future<List<Entry>> taker = async(() -> space.take(ref, Timeout.INFINITE));
        awaitBlocked(ref, 3);
        space.write(ref, Timeout.TRY_ONCE, num(7));
        assertEquals(nums(7), result(reader1));
        assertEquals(nums(7), result(reader2));
        assertEquals(nums(7), result(taker));
        assertSize(ref, 0);
    }

    // ---- wake-ups with an error ----

    @Test
    void destroyingTheContainerWakesEveryWaiterWithAClearError() throws Exception {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(1));
        ContainerRef empty = container(Order.FIFO);
        space.write(ref, Timeout.TRY_ONCE, num(1));
        Future<?> writer = async(() -> {
            space.write(ref, Timeout.INFINITE, num(2));
            return null;
        });
        Future<?> reader = async(() -> space.read(ref, Timeout.INFINITE, Selector.fifo(Selector.ALL),
                Selector.template(Template.value(num(5)))));
        awaitBlocked(ref, 2);
        Future<?> taker = async(() -> space.take(empty, Timeout.INFINITE));
        Future<?> destroyer = async(() -> space.destroy(empty, Timeout.ofMillis(SOON.toMillis() * 2)));
        awaitBlocked(empty, 2);

        space.destroyContainer(ref);
        space.destroyContainer(empty);
        for (Future<?> waiter : List.of(writer, reader, taker, destroyer)) {
            ExecutionException failure = assertThrows(ExecutionException.class,
                    () -> waiter.get(SOON.toMillis(), TimeUnit.MILLISECONDS));
            assertInstanceOf(ContainerDestroyedException.class, failure.getCause());
        }
    }

    @Test
    void closingTheSpaceWakesWaiters() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        Future<?> taker = async(() -> space.take(ref, Timeout.INFINITE));
        awaitBlocked(ref, 1);
        space.close();
        ExecutionException failure = assertThrows(ExecutionException.class,
                () -> taker.get(SOON.toMillis(), TimeUnit.MILLISECONDS));
        assertInstanceOf(SpaceClosedException.class, failure.getCause());
    }

    @Test
    void interruptingAWaiterFailsItAndKeepsTheInterruptFlag() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        AtomicReference<Boolean> flagAfterwards = new AtomicReference<>();
        Thread waiter = new Thread(() -> {
            try {
                space.take(ref, Timeout.INFINITE);
            } catch (Throwable e) {
                thrown.set(e);
                flagAfterwards.set(Thread.currentThread().isInterrupted());
            }
        });
        waiter.start();
        awaitBlocked(ref, 1);
        waiter.interrupt();
        waiter.join(SOON.toMillis());
        assertInstanceOf(SpaceInterruptedException.class, thrown.get());
        assertEquals(Boolean.TRUE, flagAfterwards.get());
        assertEquals(0, space.describeContainer(ref).blocked());
        space.write(ref, Timeout.TRY_ONCE, num(1));
        assertSize(ref, 1); // the interrupted take did not consume it
    }

    @Test
    void waitersOnOtherContainersAreUntouched() throws Exception {
        ContainerRef doomed = container(Order.FIFO);
        ContainerRef other = container(Order.FIFO);
        Future<List<Entry>> taker = async(() -> space.take(other, Timeout.INFINITE));
        awaitBlocked(other, 1);
        space.destroyContainer(doomed);
        space.write(other, Timeout.TRY_ONCE, num(1));
        assertEquals(nums(1), result(taker));
        assertEquals(Set.of(), Set.copyOf(space.read(other, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL))));
    }
}
