package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.InvalidOperationException;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Timeout;

/** Base orders, order selectors (any order on any container), counts, and read/take/destroy basics. */
public abstract class OrderContract extends SpaceContract {

    private ContainerRef filled(Order order, long... values) {
        ContainerRef ref = container(order);
        for (long value : values) {
            space.write(ref, Timeout.TRY_ONCE, num(value)); // one by one: each write is a separate use
        }
        return ref;
    }

    private long takeOne(ContainerRef ref) {
        return values(space.take(ref, Timeout.TRY_ONCE))[0];
    }

    @Test
    void fifoReturnsOldestFirst() {
        ContainerRef ref = filled(Order.FIFO, 1, 2, 3);
        assertArrayEquals(new long[] {1, 2, 3}, new long[] {takeOne(ref), takeOne(ref), takeOne(ref)});
    }

    @Test
    void lifoReturnsNewestFirst() {
        ContainerRef ref = filled(Order.LIFO, 1, 2, 3);
        assertArrayEquals(new long[] {3, 2, 1}, new long[] {takeOne(ref), takeOne(ref), takeOne(ref)});
    }

    @Test
    void lruReturnsLeastRecentlyUsedAndReadingCountsAsUse() {
        ContainerRef ref = filled(Order.LRU, 1, 2, 3);
        assertArrayEquals(new long[] {1}, values(space.read(ref, Timeout.TRY_ONCE)));
        assertArrayEquals(new long[] {2}, values(space.read(ref, Timeout.TRY_ONCE)));
        assertArrayEquals(new long[] {3}, values(space.read(ref, Timeout.TRY_ONCE)));
        assertArrayEquals(new long[] {1}, values(space.read(ref, Timeout.TRY_ONCE)), "1 is again the least recent");
        assertEquals(2, takeOne(ref));
    }

    @Test
    void randomReturnsEveryEntryExactlyOnceAndNotInAFixedOrder() {
        ContainerRef ref = filled(Order.RANDOM, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20);
        Set<Long> firstReads = new HashSet<>();
        for (int i = 0; i < 60; i++) {
            firstReads.add(values(space.read(ref, Timeout.TRY_ONCE))[0]);
        }
        assertTrue(firstReads.size() > 1, "60 random reads always gave the same entry");
        Set<Long> taken = new HashSet<>();
        for (int i = 0; i < 20; i++) {
            assertTrue(taken.add(takeOne(ref)), "taken twice");
        }
        assertEquals(20, taken.size());
        assertSize(ref, 0);
    }

    @ParameterizedTest
    @EnumSource(Order.class)
    void everyOrderCanBeSelectedWhateverTheBaseOrder(Order baseOrder) {
        ContainerRef ref = filled(baseOrder, 1, 2, 3, 4, 5);
        assertArrayEquals(new long[] {1, 2, 3}, values(space.read(ref, Timeout.TRY_ONCE, Selector.fifo(3))));
        assertArrayEquals(new long[] {5, 4}, values(space.read(ref, Timeout.TRY_ONCE, Selector.lifo(2))));
        // use order now: 1, 2, 3 (first read), then 5, 4
        assertArrayEquals(new long[] {1, 2, 3, 5, 4}, values(space.read(ref, Timeout.TRY_ONCE, Selector.lru(5))));
        List<Entry> random = space.read(ref, Timeout.TRY_ONCE, Selector.random(5));
        assertEquals(Set.copyOf(nums(1, 2, 3, 4, 5)), Set.copyOf(random));
        assertEquals(5, random.size(), "distinct entries");
        assertArrayEquals(new long[] {5}, values(space.take(ref, Timeout.TRY_ONCE, Selector.lifo())));
        assertArrayEquals(new long[] {1}, values(space.take(ref, Timeout.TRY_ONCE, Selector.fifo())));
    }

    @ParameterizedTest
    @EnumSource(Order.class)
    void withoutSelectorTheBaseOrderChoosesOneEntry(Order baseOrder) {
        ContainerRef ref = filled(baseOrder, 1, 2, 3);
        long expected = switch (baseOrder) {
            case FIFO, LRU -> 1;
            case LIFO -> 3;
            case RANDOM -> -1;
        };
        long taken = takeOne(ref);
        if (expected >= 0) {
            assertEquals(expected, taken);
        }
        assertSize(ref, 2);
    }

    @Test
    void countAllReturnsEverythingInOrder() {
        ContainerRef ref = filled(Order.FIFO, 1, 2, 3, 4);
        assertArrayEquals(new long[] {1, 2, 3, 4}, values(space.read(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL))));
        assertArrayEquals(new long[] {4, 3, 2, 1}, values(space.take(ref, Timeout.TRY_ONCE, Selector.lifo(Selector.ALL))));
        assertSize(ref, 0);
    }

    @Test
    void countAllOnAnEmptyContainerReturnsNothingWithoutWaiting() {
        ContainerRef ref = container(Order.FIFO);
        assertEquals(List.of(), space.take(ref, Timeout.INFINITE, Selector.fifo(Selector.ALL)));
        assertEquals(List.of(), space.read(ref, Timeout.TRY_ONCE, Selector.random(Selector.ALL)));
    }

    @Test
    void notEnoughEntriesIsATimeoutAndChangesNothing() {
        ContainerRef ref = filled(Order.FIFO, 1, 2);
        assertThrows(SpaceTimeoutException.class, () -> space.take(ref, Timeout.TRY_ONCE, Selector.fifo(3)));
        assertSize(ref, 2);
        assertThrows(SpaceTimeoutException.class, () -> space.take(container(Order.LIFO), Timeout.TRY_ONCE));
    }

    @Test
    void readLeavesTakeRemovesDestroyRemovesAndCounts() {
        ContainerRef ref = filled(Order.FIFO, 1, 2, 3, 4);
        assertArrayEquals(new long[] {1, 2}, values(space.read(ref, Timeout.TRY_ONCE, Selector.fifo(2))));
        assertSize(ref, 4);
        assertArrayEquals(new long[] {1}, values(space.take(ref, Timeout.TRY_ONCE)));
        assertSize(ref, 3);
        assertEquals(2, space.destroy(ref, Timeout.TRY_ONCE, Selector.fifo(2)));
        assertArrayEquals(new long[] {4}, values(space.read(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL))));
        assertEquals(1, space.destroy(ref, Timeout.TRY_ONCE));
        assertEquals(0, space.destroy(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL)));
    }

    @Test
    void countAboveCapacityCanNeverSucceedAndIsRejected() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(2));
        assertThrows(InvalidOperationException.class, () -> space.read(ref, Timeout.INFINITE, Selector.fifo(3)));
    }

    @Test
    void multiEntryWriteKeepsItsOrder() {
        ContainerRef ref = container(Order.FIFO);
        space.write(ref, Timeout.TRY_ONCE, numArray(1, 2, 3));
        assertArrayEquals(new long[] {1, 2, 3}, values(space.take(ref, Timeout.TRY_ONCE, Selector.fifo(3))));
    }
}
