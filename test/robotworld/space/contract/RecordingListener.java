package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.fail;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.SubscriptionEnd;

/**
 * A listener that records what it receives and lets a test wait for it. Optionally it holds every delivery at a
 * gate until the test opens it, to play a slow listener.
 */
public final class RecordingListener implements NotificationListener {

    private final List<Notification> received = new ArrayList<>();
    private final List<String> threads = new ArrayList<>();
    private final CountDownLatch ended = new CountDownLatch(1);
    private final CountDownLatch gate;
    private final CountDownLatch entered = new CountDownLatch(1);
    private volatile SubscriptionEnd endReason;
    private volatile int endCalls;

    private RecordingListener(boolean gated) {
        this.gate = new CountDownLatch(gated ? 1 : 0);
    }

    /** Records at once. */
    public static RecordingListener recording() {
        return new RecordingListener(false);
    }

    /** Blocks in every callback until {@link #open()}. */
    public static RecordingListener gated() {
        return new RecordingListener(true);
    }

    public void open() {
        gate.countDown();
    }

    @Override
    public void onNotification(Notification notification) {
        passGate();
        synchronized (this) {
            received.add(notification);
            threads.add(Thread.currentThread().getName());
            notifyAll();
        }
    }

    @Override
    public void onEnd(SubscriptionEnd reason) {
        passGate();
        endReason = reason;
        endCalls++;
        ended.countDown();
    }

    public synchronized List<Notification> received() {
        return List.copyOf(received);
    }

    /** Waits until at least {@code count} notifications arrived; returns them all. */
    public synchronized List<Notification> awaitCount(int count, Duration within) {
        long deadline = System.nanoTime() + within.toNanos();
        while (received.size() < count) {
            long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (left <= 0) {
                fail("expected " + count + " notifications, got " + received.size() + ": " + received);
            }
            try {
                wait(left);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError(e);
            }
        }
        return List.copyOf(received);
    }

    /** Waits for the end signal; returns its reason. */
    public SubscriptionEnd awaitEnd(Duration within) {
        try {
            if (!ended.await(within.toMillis(), TimeUnit.MILLISECONDS)) {
                fail("subscription did not end; received " + received());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
        return endReason;
    }

    /** The end reason, or null if not ended yet. */
    public SubscriptionEnd endReason() {
        return endReason;
    }

    public int endCalls() {
        return endCalls;
    }

    /** Waits until a callback has been entered (for a gated listener: is now held at the gate). */
    public void awaitEntered(Duration within) {
        try {
            if (!entered.await(within.toMillis(), TimeUnit.MILLISECONDS)) {
                fail("listener was never called");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }

    private void passGate() {
        entered.countDown();
        try {
            gate.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
