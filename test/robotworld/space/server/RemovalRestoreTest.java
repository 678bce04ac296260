package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.EnumSet;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Removal;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.contract.RecordingListener;

/** The space's undo of a take ({@link EmbeddedSpace#removeWithReceipt}): what the server relies on to lose nothing. */
class RemovalRestoreTest {

    private final EmbeddedSpace space = EmbeddedSpace.open();

    @AfterEach
    void close() {
        space.close();
    }

    private static List<Entry> nums(long... values) {
        return java.util.Arrays.stream(values).mapToObj(Entry::of).map(Entry.class::cast).toList();
    }

    @Test
    void restoredEntriesGoBackToTheirPlaceInEveryOrder() {
        ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
        space.write(ref, Timeout.TRY_ONCE, Entry.of(1), Entry.of(2), Entry.of(3));
        space.read(ref, Timeout.TRY_ONCE, Selector.fifo(3)); // all used once, in order
        Removal removal = space.removeWithReceipt(ref, Operation.TAKE, Timeout.TRY_ONCE, Selector.fifo(2));
        assertEquals(nums(1, 2), removal.entries());
        space.write(ref, Timeout.TRY_ONCE, Entry.of(4));
        RecordingListener listener = RecordingListener.recording();
        space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE, Timeout.INFINITE, listener);
        removal.restore();
        removal.restore(); // idempotent
        assertEquals(nums(1, 2, 3, 4), space.read(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL)));
        assertEquals(nums(4, 3, 2, 1), space.read(ref, Timeout.TRY_ONCE, Selector.lifo(Selector.ALL)));
        assertEquals(nums(1, 2), listener.awaitCount(1, Duration.ofSeconds(5)).get(0).entries(),
                "observers see the entries come back as a write");
    }

    @Test
    void aRestoreWaitsForItsKeyAndRoomAndGoesFirst() throws Exception {
        ContainerRef ref = space.createContainer(ContainerSpec.of(Order.LIFO).withKeyView().bounded(1));
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("host-a", Entry.of("answer 1"))));
        Removal removal = space.removeWithReceipt(ref, Operation.TAKE, Timeout.TRY_ONCE, Selector.key("host-a"));
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("host-a", Entry.of("answer 2"))));

        removal.restore(); // key taken and container full: the restore waits, first in line
        assertEquals(1, space.describeContainer(ref).blocked());
        assertEquals(List.of(Entry.of("answer 2")), space.take(ref, Timeout.TRY_ONCE, Selector.key("host-a")));
        assertEquals(List.of(Entry.of("answer 1")), space.read(ref, Timeout.TRY_ONCE, Selector.key("host-a")));
        assertEquals(0, space.describeContainer(ref).blocked());
    }

    @Test
    void aRestoreOfADestroyedContainerDoesNothing() {
        ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO).withVectorView());
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(7, Entry.of("x"))));
        Removal removal = space.removeWithReceipt(ref, Operation.DESTROY, Timeout.TRY_ONCE, Selector.vector(7));
        space.destroyContainer(ref);
        removal.restore();
        assertEquals(List.of(Entry.of("x")), removal.entries());
    }

    @Test
    void aRestoredEntryKeepsItsVectorPosition() {
        ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO).withVectorView());
        space.write(ref, Timeout.TRY_ONCE, Entry.of(10), Entry.of(11), Entry.of(12));
        Removal removal = space.removeWithReceipt(ref, Operation.TAKE, Timeout.TRY_ONCE, Selector.vector(1));
        removal.restore();
        assertEquals(nums(10, 11, 12), space.read(ref, Timeout.TRY_ONCE, Selector.vector(0, 3)));
    }
}
