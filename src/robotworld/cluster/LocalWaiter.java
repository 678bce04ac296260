package robotworld.cluster;

import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;

/**
 * The member-side half of a queued operation: the thread that waits for it sleeps here until a wake-up says the
 * container served it (or it is time to look anyway), then collects the result from the container. An operation
 * that waits without a thread ({@link AsyncWaiter}) is called back instead.
 */
final class LocalWaiter {

    private final OpId id;
    private final Semaphore signals = new Semaphore(0);
    /** For an operation waiting without a thread: what a wake-up runs (it must not block). */
    private final Runnable onWake;
    private volatile boolean closed;

    LocalWaiter(OpId id) {
        this(id, null);
    }

    LocalWaiter(OpId id, Runnable onWake) {
        this.id = id;
        this.onWake = onWake;
    }

    OpId id() {
        return id;
    }

    /** The container may have served it: look. */
    void wake() {
        if (onWake != null) {
            onWake.run();
        } else {
            signals.release();
        }
    }

    /** Its space handle was closed: stop waiting. */
    void close() {
        closed = true;
        wake();
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
