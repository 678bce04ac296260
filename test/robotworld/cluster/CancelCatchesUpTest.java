package robotworld.cluster;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.EnumSet;
import java.util.List;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;
import robotworld.space.contract.RecordingListener;

/**
 * A cancel delivers what happened before it, also when the events of those calls are still on their way to the
 * subscription's member (calls made through other members pass them on as messages): the cancel reads them from
 * the container's journal first. (The served contract suite, whose calls go to one member after another, lost
 * such events now and then.)
 */
@org.junit.jupiter.api.Timeout(120)
class CancelCatchesUpTest {

    @Test
    void aCancelDeliversTheEventsStillOnTheirWayFirst() throws Exception {
        try (LocalCluster cluster = LocalCluster.startPatient(1)) {
            ClusterSpace space = cluster.member(0).openSpace("cancel-" + System.nanoTime());
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            RecordingListener listener = RecordingListener.gated();
            Subscription subscription = space.subscribe(queue, EnumSet.of(Operation.WRITE),
                    NotificationMode.INFINITE, Timeout.INFINITE, listener);
            space.node().dropEvents = true;
            try {
                for (long i = 1; i <= 3; i++) {
                    space.write(queue, Timeout.TRY_ONCE, Entry.of(i));
                }
                subscription.cancel();
                space.write(queue, Timeout.TRY_ONCE, Entry.of(4));
            } finally {
                space.node().dropEvents = false;
            }
            listener.open();
            assertEquals(SubscriptionEnd.CANCELLED, listener.awaitEnd(Duration.ofSeconds(20)));
            assertEquals(List.of(List.of(Entry.of(1)), List.of(Entry.of(2)), List.of(Entry.of(3))),
                    listener.received().stream().map(Notification::entries).toList());
        }
    }
}
