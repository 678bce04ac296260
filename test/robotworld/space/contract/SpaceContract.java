package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;

import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.Order;

/**
 * Base of the {@link Capi} contract suites. A suite runs against any implementation: subclass it (typically as a
 * {@code @Nested} class of one test class per implementation) and say how to open a fresh space.
 *
 * <p>Waiting in these tests is always on a condition with a deadline, never a fixed sleep: a blocked operation
 * is recognised by the container's {@code blocked} count.
 */
// a hang guard above SOON, so that a test waiting for SOON fails with its own message: on a busy 2-core machine the
// thousands of calls of the stress tests through a served cluster take longer than 30 s
@org.junit.jupiter.api.Timeout(value = 360)
public abstract class SpaceContract {

    /**
     * Generous bound for things that should happen "soon"; only reached when a test is failing. It is a hang
     * guard, not a speed check (speed lives in the benchmarks): sized so that the stress tests' thousands of
     * remote calls finish even on a 2-core machine that is busy with other work (with two CPU-bound processes per
     * core beside it, the 9 000 writes and takes of the bounded-queue test through a served cluster took over 60 s).
     */
    protected static final Duration SOON = Duration.ofSeconds(180);
    /** Queue size for ordinary tests: far more than any of them produces. */
    protected static final int LARGE_QUEUE = 100_000;

    protected Capi space;
    private ExecutorService threads;

    /** A fresh, empty space whose subscriptions each queue at most {@code notificationQueue} notifications. */
    protected abstract Capi newSpace(int notificationQueue);

    @BeforeEach
    void openSpace() {
        space = newSpace(LARGE_QUEUE);
        threads = Executors.newCachedThreadPool();
    }

    @AfterEach
    void closeSpace() throws InterruptedException {
        space.close();
        threads.shutdownNow();
        if (!threads.awaitTermination(5, TimeUnit.SECONDS)) {
            fail("test threads did not stop");
        }
    }

    // ---- containers and entries ----

    protected ContainerRef container(ContainerSpec spec) {
        return space.createContainer(spec);
    }

    protected ContainerRef container(Order order) {
        return space.createContainer(ContainerSpec.of(order));
    }

    protected static IntEntry num(long value) {
        return Entry.of(value);
    }

    protected static List<Entry> nums(long... values) {
        List<Entry> entries = new ArrayList<>();
        for (long value : values) {
            entries.add(Entry.of(value));
        }
        return entries;
    }

    protected static Entry[] numArray(long... values) {
        return nums(values).toArray(new Entry[0]);
    }

    protected static long[] values(List<Entry> entries) {
        return entries.stream().mapToLong(entry -> ((IntEntry) entry).value()).toArray();
    }

    // ---- threads and waiting ----

    /** Runs {@code task} on another thread. */
    protected <T> Future<T> async(Callable<T> task) {
        return threads.submit(task);
    }

    /** The result of {@code future}, failing the test if it takes longer than {@link #SOON}. */
    protected static <T> T result(Future<T> future) throws Exception {
        try {
            return future.get(SOON.toMillis(), TimeUnit.MILLISECONDS);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Exception cause) {
                throw cause;
            }
            throw e;
        }
    }

    /** Waits until {@code condition} holds, failing the test after {@link #SOON}. */
    protected static void eventually(String what, BooleanSupplier condition) {
        long deadline = System.nanoTime() + SOON.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                fail("timed out waiting until " + what);
            }
            pause();
        }
    }

    /** Waits until {@code count} operations are blocked on {@code container}. */
    protected void awaitBlocked(ContainerRef container, int count) {
        eventually(count + " operation(s) blocked on " + container,
                () -> space.describeContainer(container).blocked() == count);
    }

    protected void assertSize(ContainerRef container, int size) {
        assertEquals(size, space.describeContainer(container).size(), "size of " + container);
    }

    private static void pause() {
        try {
            Thread.sleep(1);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        }
    }
}
