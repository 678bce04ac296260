package robotworld.xvsm;

import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The threads that serve the Local sides of this program: a small pool ({@code xvsm-serve-N}) that carries out
 * requests on the hardware and hands answers to the space, shared by every module, plus one timer thread for the
 * pauses after space failures. Waiting for requests takes no thread (see {@link RequestServer}), so the number of
 * threads follows the hardware calls in progress, not the number of modules served. The pool grows on demand up to
 * {@code rwe.serve.threads} (default 32), and idle threads end after 10 s; daemon threads, so they never keep a
 * program alive.
 */
final class ServingThreads {

    private static final Logger LOG = LoggerFactory.getLogger(ServingThreads.class);
    private static final int THREADS = Math.max(2, Integer.getInteger("rwe.serve.threads", 32));
    private static final ThreadPoolExecutor POOL = pool();
    private static final ScheduledThreadPoolExecutor TIMER = timer();

    private ServingThreads() {
    }

    private static ThreadPoolExecutor pool() {
        AtomicInteger count = new AtomicInteger();
        ThreadPoolExecutor pool = new ThreadPoolExecutor(THREADS, THREADS, 10, TimeUnit.SECONDS,
                new LinkedBlockingQueue<>(), task -> {
                    Thread thread = new Thread(task, "xvsm-serve-" + count.incrementAndGet());
                    thread.setDaemon(true);
                    thread.setUncaughtExceptionHandler((dead, error) -> LOG.error("a serving thread died", error));
                    return thread;
                });
        pool.allowCoreThreadTimeOut(true);
        return pool;
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

    /** Runs {@code task} on a serving thread. */
    static void execute(Runnable task) {
        try {
            POOL.execute(task);
        } catch (RejectedExecutionException e) {
            LOG.error("cannot hand a module's requests to a serving thread", e); // never happens: an unbounded queue
        }
    }

    /** Runs {@code task} on a serving thread after {@code millis}. */
    static void schedule(Runnable task, long millis) {
        TIMER.schedule(() -> execute(task), millis, TimeUnit.MILLISECONDS);
    }
}
