package robotworld.space.internal;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The threads a space uses: a growing pool that runs notification listeners (so one slow listener holds one
 * thread, never a space operation or another listener), one timer thread for subscription timeouts, and one that
 * times out operations waiting without a thread ({@link WaitTimer}). All are daemon threads, created only when
 * first needed. Shared with the clustered space, whose subscriptions are delivered the same way on the member
 * where they were made.
 */
public final class Delivery {

    private final String name;
    private ExecutorService listeners;
    private ScheduledExecutorService timer;
    private final WaitTimer waits;
    private boolean closed;

    /** Threads named after {@code name}. */
    public Delivery(String name) {
        this.name = name;
        this.waits = new WaitTimer(name);
    }

    /** Runs {@code task} after {@code delayNanos}, for a wait's timeout (see {@link WaitTimer}); null once closed. */
    WaitTimer.Timeout timeout(Runnable task, long delayNanos) {
        return waits.schedule(task, delayNanos);
    }

    /** Runs {@code task} on a listener thread; ignored once closed. */
    void execute(Runnable task) {
        ExecutorService pool;
        synchronized (this) {
            if (closed) {
                return;
            }
            if (listeners == null) {
                listeners = Executors.newCachedThreadPool(daemonThreads(name + "-notify"));
            }
            pool = listeners;
        }
        try {
            pool.execute(task);
        } catch (RejectedExecutionException closedMeanwhile) {
            // the space is closing; nothing is waiting for this delivery any more
        }
    }

    /** Runs {@code task} on the timer thread after {@code delayNanos}; null once closed. */
    ScheduledFuture<?> schedule(Runnable task, long delayNanos) {
        ScheduledExecutorService scheduler;
        synchronized (this) {
            if (closed) {
                return null;
            }
            if (timer == null) {
                ScheduledThreadPoolExecutor executor = new ScheduledThreadPoolExecutor(1, daemonThreads(name + "-timer"));
                executor.setRemoveOnCancelPolicy(true);
                timer = executor;
            }
            scheduler = timer;
        }
        try {
            return scheduler.schedule(task, delayNanos, TimeUnit.NANOSECONDS);
        } catch (RejectedExecutionException closedMeanwhile) {
            return null;
        }
    }

    /** Stops accepting work; listener tasks already submitted still run, so final signals get delivered. */
    public synchronized void close() {
        closed = true;
        waits.close();
        if (listeners != null) {
            listeners.shutdown();
        }
        if (timer != null) {
            timer.shutdownNow();
        }
    }

    private static ThreadFactory daemonThreads(String prefix) {
        AtomicInteger count = new AtomicInteger();
        return task -> {
            Thread thread = new Thread(task, prefix + "-" + count.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        };
    }
}
