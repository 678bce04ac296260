package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.EnumSet;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Timeout;
import robotworld.space.contract.RecordingListener;

/**
 * Notifications that reach the client before its subscribe answer wait for the subscription, and those that come
 * while they are being handed over wait behind them: the listener sees the container's order. (A monitor that
 * subscribed again after a failover once saw 7479, 7478, 7480: the frame that came during the hand-over went
 * straight to the listener, ahead of the one parked before it.)
 */
class EarlyFramesOrderTest {

    private static final Duration SOON = Duration.ofSeconds(20);

    @Test
    void framesArrivingWhileParkedOnesAreHandedOverComeAfterThem() throws Exception {
        try (ServedSpace served = ServedSpace.open(1_000)) {
            EventStream stream = served.client.events;
            ContainerRef queue = served.createContainer(ContainerSpec.of(Order.FIFO));
            AtomicBoolean handedOverOnce = new AtomicBoolean();
            // the answer is in, the subscription not yet registered: a write's frame arrives and is parked
            stream.beforeRegistering = () -> writeAndAwaitItsFrame(served, queue, 1);
            // the parked frame is about to be handed over: the next write's frame arrives meanwhile
            stream.beforeParkedFramesDelivered = () -> {
                if (handedOverOnce.compareAndSet(false, true)) {
                    writeAndAwaitItsFrame(served, queue, 2);
                }
            };
            RecordingListener listener = RecordingListener.recording();
            served.subscribe(queue, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE, Timeout.INFINITE,
                    listener);
            stream.beforeRegistering = null;
            assertTrue(handedOverOnce.get(), "the first write's frame was parked and handed over");
            served.write(queue, Timeout.INFINITE, Entry.of(3));

            List<Notification> received = listener.awaitCount(3, SOON);
            assertEquals(List.of(1L, 2L, 3L), received.stream().map(n -> ((robotworld.space.IntEntry) n.entries().get(0)).value()).toList(),
                    "in the order written");
            for (int i = 1; i < received.size(); i++) {
                assertEquals(received.get(i - 1).sequence() + 1, received.get(i).sequence(), "one after another");
            }
        }
    }

    private static void writeAndAwaitItsFrame(ServedSpace served, ContainerRef queue, long value) {
        long before = served.client.events.lastFrameRead();
        served.write(queue, Timeout.INFINITE, Entry.of(value));
        long giveUp = System.nanoTime() + SOON.toNanos();
        while (served.client.events.lastFrameRead() == before && System.nanoTime() < giveUp) {
            Thread.onSpinWait();
        }
        assertTrue(served.client.events.lastFrameRead() > before, "the frame of write " + value + " arrived");
    }
}
