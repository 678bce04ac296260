package robotworld.cluster;

import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;

/**
 * The member-side half of a queued operation: the thread that waits for it sleeps here until a wake-up says the
 * container served it (or it is time to look anyway), then collects the result from the container.
 */
final class LocalWaiter {

    private final OpId id;
    private final Semaphore signals = new Semaphore(0);
    private volatile boolean closed;

    LocalWaiter(OpId id) {
        this.id = id;
    }

    OpId id() {
        return id;
    }

    /** The container may have served it: look. */
    void wake() {
        signals.release();
    }

    /** Its space handle was closed: stop waiting. */
    void close() {
        closed = true;
        signals.release();
    }

    boolean isClosed() {
        return closed;
    }

    /** Sleeps until woken or {@code nanos} pass; whether it was woken. */
    boolean await(long nanos) throws InterruptedException {
        boolean woken = nanos <= 0 ? signals.tryAcquire() : signals.tryAcquire(nanos, TimeUnit.NANOSECONDS);
        if (woken) {
            signals.drainPermits(); // one look answers every wake-up so far
        }
        return woken;
    }
}
