package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robotworld.space.ContainerRef;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.testsupport.ForwardingCapi;

/**
 * A closing program's last heartbeat is the one the space keeps, though a periodic heartbeat was still under way
 * when the program closed: sent after it, the older one would replace it, and the program would look silent (as if
 * killed) instead of ended.
 */
class LastHeartbeatTest {

    @Test
    void aPeriodicHeartbeatStillUnderWayDoesNotReplaceTheLastOne() throws Exception {
        try (EmbeddedSpace data = EmbeddedSpace.open()) {
            SlowHeartbeats space = new SlowHeartbeats(data);
            SafetySupervisor supervisor = new SafetySupervisor(space, "room-pc#1", "room-pc",
                    SafetySettings.of(new Properties(), Map.of()));
            space.slow = true;
            assertTrue(space.periodicUnderWay.await(10, TimeUnit.SECONDS), "no periodic heartbeat was sent");
            supervisor.close();

            ContainerRef liveness = data.lookupContainer(SafetyContainers.LIVENESS);
            List<Entry> kept = data.read(liveness, Timeout.TRY_ONCE, Selector.key("room-pc#1"));
            Heartbeat last = Heartbeat.parse(kept.get(0));
            assertTrue(last.ended(), "the space kept " + last);
            assertEquals(space.highestSequence, last.sequence(), "the space kept an older heartbeat than the last");
        }
    }

    /** Holds up periodic heartbeats for 300 ms once told to, as a busy space or link would. */
    private static final class SlowHeartbeats extends ForwardingCapi {
        final CountDownLatch periodicUnderWay = new CountDownLatch(1);
        volatile boolean slow;
        volatile long highestSequence;

        SlowHeartbeats(EmbeddedSpace delegate) {
            super(delegate);
        }

        @Override
        public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
            Heartbeat beat;
            try {
                beat = Heartbeat.parse(items.get(0).entry());
            } catch (IllegalArgumentException notOne) {
                return super.shift(container, timeout, items);
            }
            synchronized (this) {
                highestSequence = Math.max(highestSequence, beat.sequence());
            }
            if (slow && !beat.ended()) {
                periodicUnderWay.countDown();
                try {
                    Thread.sleep(300);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            return super.shift(container, timeout, items);
        }
    }
}
