package robotworld.space;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.time.Duration;
import java.util.EnumSet;
import java.util.List;

import org.junit.jupiter.api.Test;

import robotworld.space.contract.RecordingListener;

/** What only the embedded implementation promises: its URI, its exact overflow point, its limits. */
class EmbeddedSpaceTest {

    private static final Duration SOON = Duration.ofSeconds(20); // only a failure waits that long

    @Test
    void crefsCarryTheSpaceUri() {
        URI uri = URI.create("http://127.0.0.1:4711/");
        try (EmbeddedSpace space = EmbeddedSpace.open(uri, 10)) {
            assertEquals(uri, space.spaceUri());
            assertEquals(uri, space.createContainer(ContainerSpec.defaults()).space());
        }
    }

    @Test
    void eachOpenedSpaceHasItsOwnUri() {
        try (EmbeddedSpace first = EmbeddedSpace.open(); EmbeddedSpace second = EmbeddedSpace.open()) {
            ContainerRef ref = first.createContainer(ContainerSpec.defaults());
            assertTrue(first.spaceUri().toString().startsWith("embedded:"));
            assertThrows(ContainerNotFoundException.class, () -> second.read(ref, Timeout.TRY_ONCE));
        }
    }

    @Test
    void overflowHappensExactlyWhenTheQueueIsFull() {
        int queue = 4;
        try (EmbeddedSpace space = EmbeddedSpace.open(queue)) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
            RecordingListener stuck = RecordingListener.gated();
            space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE, Timeout.INFINITE, stuck);
            space.write(ref, Timeout.TRY_ONCE, Entry.of(1));
            stuck.awaitEntered(SOON); // notification 1 is in the listener, out of the queue
            for (long i = 2; i <= 10; i++) {
                space.write(ref, Timeout.TRY_ONCE, Entry.of(i));
            }
            stuck.open();
            assertEquals(SubscriptionEnd.OVERFLOWED, stuck.awaitEnd(SOON));
            // 1 in the listener + 4 queued; the 6th write overflowed
            List<Notification> received = stuck.received();
            assertEquals(1 + queue, received.size());
            assertEquals(Entry.of(5), received.get(4).entries().get(0));
        }
    }

    @Test
    void vectorPositionsAreLimited() {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO).withVectorView());
            assertThrows(InvalidOperationException.class,
                    () -> space.write(ref, Timeout.TRY_ONCE, List.of(Item.at(1 << 20, Entry.of(1)))));
            space.write(ref, Timeout.TRY_ONCE, List.of(Item.at((1 << 20) - 1, Entry.of(1))));
            assertThrows(InvalidOperationException.class, () -> space.write(ref, Timeout.TRY_ONCE, Entry.of(2)),
                    "no position left to append at");
            assertEquals(1, space.describeContainer(ref).size());
        }
    }

    @Test
    void badQueueCapacityIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> EmbeddedSpace.open(0));
    }
}
