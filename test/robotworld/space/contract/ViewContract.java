package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.InvalidOperationException;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/** The KEY and VECTOR views: placing entries, selecting them, and blocking on occupied keys and positions. */
public abstract class ViewContract extends SpaceContract {

    private ContainerRef keyed() {
        return container(ContainerSpec.of(Order.LIFO).withKeyView());
    }

    private ContainerRef vector() {
        return container(ContainerSpec.of(Order.FIFO).withVectorView());
    }

    // ---- KEY ----

    @Test
    void keySelectsTheEntryWrittenUnderIt() {
        ContainerRef ref = keyed();
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("alpha", num(1)), Item.keyed("beta", num(2))));
        assertEquals(List.of(num(2)), space.read(ref, Timeout.TRY_ONCE, Selector.key("beta")));
        assertEquals(List.of(num(1)), space.take(ref, Timeout.TRY_ONCE, Selector.key("alpha")));
        assertThrows(SpaceTimeoutException.class, () -> space.read(ref, Timeout.TRY_ONCE, Selector.key("alpha")));
        assertSize(ref, 1);
    }

    @Test
    void keyWithCountAllGivesNothingWhenAbsentWithoutWaiting() {
        ContainerRef ref = keyed();
        assertEquals(List.of(), space.take(ref, Timeout.INFINITE, Selector.key("missing", Selector.ALL)));
    }

    @Test
    void takeByKeyWaitsForTheKeyToBeWritten() throws Exception {
        ContainerRef ref = keyed();
        Future<List<Entry>> answer = async(() -> space.take(ref, Timeout.INFINITE, Selector.key("host-a")));
        awaitBlocked(ref, 1);
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("host-b", num(1))));
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("host-a", num(2))));
        assertEquals(List.of(num(2)), result(answer));
        assertEquals(List.of(num(1)), space.read(ref, Timeout.TRY_ONCE, Selector.key("host-b")));
    }

    @Test
    void writeToAnOccupiedKeyWaitsUntilItIsFree() throws Exception {
        ContainerRef ref = keyed();
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("k", num(1))));
        assertThrows(SpaceTimeoutException.class,
                () -> space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("k", num(2)))));
        Future<?> second = async(() -> {
            space.write(ref, Timeout.INFINITE, List.of(Item.keyed("k", num(2))));
            return null;
        });
        awaitBlocked(ref, 1);
        assertEquals(List.of(num(1)), space.take(ref, Timeout.TRY_ONCE, Selector.key("k")));
        result(second);
        assertEquals(List.of(num(2)), space.read(ref, Timeout.TRY_ONCE, Selector.key("k")));
    }

    @Test
    void keyedAndUnkeyedEntriesShareTheBaseOrder() {
        ContainerRef ref = keyed();
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("k", num(1)), Item.of(num(2))));
        assertEquals(List.of(num(2), num(1)), space.read(ref, Timeout.TRY_ONCE, Selector.lifo(2)));
    }

    @Test
    void keysNeedAKeyView() {
        ContainerRef plain = container(Order.FIFO);
        assertThrows(InvalidOperationException.class, () -> space.read(plain, Timeout.TRY_ONCE, Selector.key("k")));
        assertThrows(InvalidOperationException.class,
                () -> space.write(plain, Timeout.TRY_ONCE, List.of(Item.keyed("k", num(1)))));
    }

    @Test
    void duplicateKeysInOneWriteAreRejected() {
        ContainerRef ref = keyed();
        assertThrows(InvalidOperationException.class, () -> space.write(ref, Timeout.TRY_ONCE,
                List.of(Item.keyed("k", num(1)), Item.keyed("k", num(2)))));
        assertSize(ref, 0);
    }

    // ---- VECTOR ----

    @Test
    void appendedEntriesGetConsecutivePositions() {
        ContainerRef ref = vector();
        space.write(ref, Timeout.TRY_ONCE, numArray(10, 11, 12));
        assertEquals(List.of(num(11)), space.read(ref, Timeout.TRY_ONCE, Selector.vector(1)));
        assertArrayEquals(new long[] {10, 11, 12}, values(space.read(ref, Timeout.TRY_ONCE, Selector.vector(0, 3))));
        assertArrayEquals(new long[] {11, 12}, values(space.read(ref, Timeout.TRY_ONCE, Selector.vector(1, Selector.ALL))));
    }

    @Test
    void positionsStayPutWhenOthersAreTaken() {
        ContainerRef ref = vector();
        space.write(ref, Timeout.TRY_ONCE, numArray(10, 11, 12));
        assertEquals(List.of(num(10)), space.take(ref, Timeout.TRY_ONCE, Selector.vector(0)));
        assertEquals(List.of(num(12)), space.read(ref, Timeout.TRY_ONCE, Selector.vector(2)));
        assertThrows(SpaceTimeoutException.class, () -> space.read(ref, Timeout.TRY_ONCE, Selector.vector(0, 2)),
                "position 0 is empty, so the range 0..1 is not complete");
    }

    @Test
    void explicitPositionsAndAppendsAfterThem() {
        ContainerRef ref = vector();
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(5, num(50)), Item.of(num(60)), Item.at(2, num(20))));
        assertArrayEquals(new long[] {20, 50, 60},
                values(space.read(ref, Timeout.TRY_ONCE, Selector.vector(0, Selector.ALL))));
        assertEquals(List.of(num(60)), space.read(ref, Timeout.TRY_ONCE, Selector.vector(6)));
        assertEquals(List.of(), space.read(ref, Timeout.TRY_ONCE, Selector.vector(7, Selector.ALL)));
    }

    @Test
    void appendGoesAfterTheHighestOccupiedPosition() {
        ContainerRef ref = vector();
        space.write(ref, Timeout.TRY_ONCE, numArray(0, 1, 2));
        space.take(ref, Timeout.TRY_ONCE, Selector.vector(2));
        space.write(ref, Timeout.TRY_ONCE, num(9));
        assertEquals(List.of(num(9)), space.read(ref, Timeout.TRY_ONCE, Selector.vector(2)));
    }

    @Test
    void writeToAnOccupiedPositionWaitsUntilItIsFree() throws Exception {
        ContainerRef ref = vector();
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(3, num(1))));
        assertThrows(SpaceTimeoutException.class,
                () -> space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(3, num(2)))));
        Future<?> second = async(() -> {
            space.write(ref, Timeout.INFINITE, List.of(Item.at(3, num(2))));
            return null;
        });
        awaitBlocked(ref, 1);
        space.destroy(ref, Timeout.TRY_ONCE, Selector.vector(3));
        result(second);
        assertEquals(List.of(num(2)), space.read(ref, Timeout.TRY_ONCE, Selector.vector(3)));
    }

    @Test
    void readOfAPositionWaitsUntilItIsFilled() throws Exception {
        ContainerRef ref = vector();
        Future<List<Entry>> reader = async(() -> space.read(ref, Timeout.INFINITE, Selector.vector(1, 2)));
        awaitBlocked(ref, 1);
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(1, num(1))));
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(2, num(2))));
        assertEquals(nums(1, 2), result(reader));
    }

    @Test
    void positionsNeedAVectorView() {
        ContainerRef plain = container(Order.FIFO);
        assertThrows(InvalidOperationException.class, () -> space.read(plain, Timeout.TRY_ONCE, Selector.vector(0)));
        assertThrows(InvalidOperationException.class,
                () -> space.write(plain, Timeout.TRY_ONCE, List.of(Item.at(0, num(1)))));
    }

    @Test
    void duplicatePositionsInOneWriteAreRejected() {
        ContainerRef ref = vector();
        assertThrows(InvalidOperationException.class,
                () -> space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(1, num(1)), Item.at(1, num(2)))));
    }

    @Test
    void bothViewsOnOneContainer() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).withKeyView().withVectorView());
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("a", Tuple.of("a", 1)).atIndex(4)));
        assertEquals(space.read(ref, Timeout.TRY_ONCE, Selector.key("a")),
                space.read(ref, Timeout.TRY_ONCE, Selector.vector(4)));
        space.take(ref, Timeout.TRY_ONCE, Selector.key("a"));
        assertThrows(SpaceTimeoutException.class, () -> space.read(ref, Timeout.TRY_ONCE, Selector.vector(4)));
    }
}
