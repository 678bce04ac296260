package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.time.Duration;
import java.util.EnumSet;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;
import robotworld.space.contract.RecordingListener;

/**
 * What the client asks the server for when it establishes a subscription, and the part of a PROLONG period it
 * keeps itself. The server restarts the timeout it is given at every firing, so a PROLONG subscription must be
 * given its whole timeout, however long after subscribing it is established.
 */
class RemoteSubscriptionTest {

    private static final Duration SOON = Duration.ofSeconds(60);
    private static final ContainerRef CONTAINER = new ContainerRef(URI.create("xvsm://localhost:9876"), "jobs");

    private final ExecutorService delivery = Executors.newCachedThreadPool();
    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
    private final RecordingListener listener = RecordingListener.recording();
    private final AtomicInteger cancels = new AtomicInteger();

    @AfterEach
    void stop() {
        delivery.shutdownNow();
        timer.shutdownNow();
    }

    private RemoteSubscription subscription(NotificationMode mode, Timeout timeout) {
        return new RemoteSubscription(CONTAINER, EnumSet.of(Operation.WRITE), mode, timeout, listener, 100, delivery,
                cancelled -> cancels.incrementAndGet());
    }

    @Test
    void prolongAsksForItsWholeTimeoutHoweverLateItIsEstablished() throws Exception {
        RemoteSubscription prolong = subscription(NotificationMode.PROLONG, Timeout.ofMillis(3_000));
        Thread.sleep(30); // the stream took a while to connect
        assertEquals(Timeout.ofMillis(3_000), prolong.timeoutOnServer(), "every period restarts this on the server");
    }

    @Test
    void onceAndRestrictedAskForWhatIsLeft() throws Exception {
        RemoteSubscription once = subscription(NotificationMode.ONCE, Timeout.ofMillis(3_000));
        RemoteSubscription restricted = subscription(NotificationMode.RESTRICTED, Timeout.ofMillis(3_000));
        Thread.sleep(30);
        assertTrue(once.timeoutOnServer().millis() <= 2_970, once.timeoutOnServer().toString());
        assertTrue(restricted.timeoutOnServer().millis() <= 2_970, restricted.timeoutOnServer().toString());
    }

    @Test
    void aProlongPeriodWithoutFiringEndsOnTheClientWhenItsServerStartedLater() throws Exception {
        long subscribed = System.nanoTime();
        RemoteSubscription prolong = subscription(NotificationMode.PROLONG, Timeout.ofMillis(200));
        prolong.established(timer);
        assertEquals(SubscriptionEnd.EXPIRED, listener.awaitEnd(SOON));
        assertTrue(System.nanoTime() - subscribed >= Duration.ofMillis(200).toNanos(), "not before the timeout");
        assertTrue(!prolong.isActive());
        long giveUp = System.nanoTime() + SOON.toNanos();
        while (cancels.get() == 0 && System.nanoTime() < giveUp) {
            Thread.sleep(1);
        }
        assertEquals(1, cancels.get(), "taken off the server");
    }
}
