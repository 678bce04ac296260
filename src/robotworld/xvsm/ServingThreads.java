package robotworld.xvsm;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The threads that serve the Local sides of this program: a small pool ({@code xvsm-serve-N}) that carries out
 * requests on the hardware and hands answers to the space, shared by every module, plus one timer thread for the
 * pauses after space failures. Waiting for requests takes no thread (see {@link RequestServer}), so the number of
 * threads follows the hardware calls in progress, not the number of modules served: a thread is started only when
 * work arrives and every serving thread is busy, up to {@code rwe.serve.threads} (default 32; then work queues),
 * and idle threads end after 10 s. Daemon threads, so they never keep a program alive.
 */
final class ServingThreads {

    private static final Logger LOG = LoggerFactory.getLogger(ServingThreads.class);
    private static final int MAX_THREADS = Math.max(1, Integer.getInteger("rwe.serve.threads", 32));
    private static final ConcurrentLinkedQueue<Runnable> TASKS = new ConcurrentLinkedQueue<>();
    /** Threads taking tasks from {@link #TASKS}, and how many of them run one right now. */
    private static final AtomicInteger WORKERS = new AtomicInteger();
    private static final AtomicInteger BUSY = new AtomicInteger();
    private static final ThreadPoolExecutor THREADS = threads();
    private static final ScheduledThreadPoolExecutor TIMER = timer();

    private ServingThreads() {
    }

    private static ThreadPoolExecutor threads() {
        AtomicInteger count = new AtomicInteger();
        // the threads themselves: kept 10 s for reuse, none while nothing is served
        return new ThreadPoolExecutor(0, MAX_THREADS, 10, TimeUnit.SECONDS, new SynchronousQueue<>(), task -> {
            Thread thread = new Thread(task, "xvsm-serve-" + count.incrementAndGet());
            thread.setDaemon(true);
            thread.setUncaughtExceptionHandler((dead, error) -> LOG.error("a serving thread died", error));
            return thread;
        });
    }

    private static ScheduledThreadPoolExecutor timer() {
        ScheduledThreadPoolExecutor timer = new ScheduledThreadPoolExecutor(1, task -> {
            Thread thread = new Thread(task, "xvsm-serve-timer");
            thread.setDaemon(true);
            return thread;
        });
        timer.setRemoveOnCancelPolicy(true);
        return timer;
    }

    /** Runs {@code task} on a serving thread: an idle one, a new one while fewer than the maximum run, or later. */
    static void execute(Runnable task) {
        TASKS.add(task);
        if (WORKERS.get() - BUSY.get() <= 0) {
            startWorker();
        }
    }

    /** Runs {@code task} on a serving thread after {@code millis}. */
    static void schedule(Runnable task, long millis) {
        TIMER.schedule(() -> execute(task), millis, TimeUnit.MILLISECONDS);
    }

    private static void startWorker() {
        while (true) {
            int workers = WORKERS.get();
            if (workers >= MAX_THREADS) {
                return; // a busy worker takes it when it is done
            }
            if (WORKERS.compareAndSet(workers, workers + 1)) {
                try {
                    THREADS.execute(ServingThreads::work);
                } catch (RejectedExecutionException e) {
                    WORKERS.decrementAndGet();
                    LOG.error("cannot start a serving thread", e);
                }
                return;
            }
        }
    }

    private static void work() {
        while (true) {
            Runnable task = TASKS.poll();
            if (task == null) {
                WORKERS.decrementAndGet();
                // a task added just now may have counted on this worker: take it back up if so
                if (TASKS.isEmpty() || !rejoin()) {
                    return;
                }
                continue;
            }
            BUSY.incrementAndGet();
            try {
                task.run();
            } catch (RuntimeException e) {
                LOG.error("a serving task failed", e); // RequestServer catches what it expects
            } finally {
                BUSY.decrementAndGet();
            }
        }
    }

    private static boolean rejoin() {
        while (true) {
            int workers = WORKERS.get();
            if (workers >= MAX_THREADS) {
                return false;
            }
            if (WORKERS.compareAndSet(workers, workers + 1)) {
                return true;
            }
        }
    }
}
