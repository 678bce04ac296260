package robotworld.space.remote;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One thread for the whole JVM that looks every {@value #TICK_MILLIS} ms for take confirmations that have waited
 * too long for a request to ride on, and has their space send them alone ({@link AckQueue#sweep}).
 *
 * <p>Why not each space's own timer: scheduling a flush after every take woke that space's timer thread twice per
 * quiet spell (once to take the new task, once to run it), even though the next request nearly always carried the
 * confirmation first. With 100 busy clients that was about 10 000 thread wake-ups a second and a quarter of the
 * clients' CPU per module call. The sweeper wakes every {@value #TICK_MILLIS} ms while a confirmation is
 * outstanding anywhere in the JVM, and parks after a second without any, until the next one wakes it.
 *
 * <p>The sweeper never does I/O: a queue that has to be flushed hands the flush to its space's timer. It never
 * dies: a failing queue is logged and skipped.
 */
final class AckSweeper implements Runnable {

    private static final long TICK_MILLIS = 5;
    private static final long TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(TICK_MILLIS);
    /** How long the sweeper keeps ticking without any confirmation outstanding before it parks. */
    private static final long DORMANT_AFTER_NANOS = TimeUnit.SECONDS.toNanos(1);
    private static final Logger LOG = LoggerFactory.getLogger(AckSweeper.class);
    private static final AckSweeper SHARED = new AckSweeper(true);

    private final Set<AckQueue> queues = ConcurrentHashMap.newKeySet();
    /** True while the sweeper is parked without a deadline; {@link #pending()} then wakes it. */
    private volatile boolean dormant = true;
    /** False for a sweeper whose sweeps a test calls itself. */
    private final boolean ticking;
    /** Read by {@link #pending()} on any thread: volatile, or a wake-up could go to null and be lost. */
    private volatile Thread thread;

    AckSweeper(boolean ticking) {
        this.ticking = ticking;
    }

    static AckSweeper shared() {
        return SHARED;
    }

    void register(AckQueue queue) {
        queues.add(queue);
        synchronized (this) {
            if (ticking && thread == null) {
                thread = new Thread(this, "space-ack-sweeper");
                thread.setDaemon(true);
                thread.start();
            }
        }
    }

    void unregister(AckQueue queue) {
        queues.remove(queue);
    }

    /** A confirmation was queued: wakes the sweeper if it is parked for good. Cheap when it is ticking. */
    void pending() {
        if (dormant && ticking) {
            dormant = false;
            LockSupport.unpark(thread);
        }
    }

    @Override
    public void run() {
        long lastOutstanding = System.nanoTime();
        while (true) {
            if (dormant) {
                LockSupport.park(this);
            } else {
                LockSupport.parkNanos(this, TICK_NANOS);
            }
            long now = System.nanoTime();
            if (sweepAll(now)) {
                lastOutstanding = now;
            } else if (now - lastOutstanding > DORMANT_AFTER_NANOS) {
                dormant = true;
                // a confirmation queued while this sweep ran saw dormant still false and did not wake us
                if (sweepAll(now)) {
                    dormant = false;
                    lastOutstanding = now;
                }
            }
        }
    }

    /** Sweeps every queue; true if any had confirmations outstanding. */
    private boolean sweepAll(long now) {
        boolean outstanding = false;
        for (AckQueue queue : queues) {
            try {
                outstanding |= queue.sweep(now);
            } catch (RuntimeException | Error e) {
                LOG.warn("sweeping take confirmations failed; trying again on the next tick", e);
                outstanding = true;
            }
        }
        return outstanding;
    }
}
