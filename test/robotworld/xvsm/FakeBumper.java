package robotworld.xvsm;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import robotworld.core.BumperModule;

/**
 * A bumper module for tests: answers {@code getAllBumper} with the values it is given, one per read, and counts
 * reads; a read can be held until the test lets it go, to have a call in progress at a chosen moment.
 */
final class FakeBumper implements BumperModule {

    private final BlockingQueue<Integer> masks = new LinkedBlockingQueue<>();
    private final AtomicInteger reads = new AtomicInteger();
    private volatile CountDownLatch gate = new CountDownLatch(0);
    private final CountDownLatch entered = new CountDownLatch(1);
    private volatile RuntimeException failure;

    /** The masks the next reads return, in order; without one, a read returns 0. */
    FakeBumper thenReturn(int... values) {
        for (int value : values) {
            masks.add(value);
        }
        return this;
    }

    /** Holds every read until {@link #release()}. */
    FakeBumper hold() {
        gate = new CountDownLatch(1);
        return this;
    }

    void release() {
        gate.countDown();
    }

    /** Makes every read throw {@code e} (null: read normally). */
    void failWith(RuntimeException e) {
        failure = e;
    }

    /** Waits until a read has started. */
    boolean awaitRead(long millis) throws InterruptedException {
        return entered.await(millis, TimeUnit.MILLISECONDS);
    }

    int reads() {
        return reads.get();
    }

    @Override
    public int getAllBumper() {
        reads.incrementAndGet();
        entered.countDown();
        try {
            if (!gate.await(10, TimeUnit.SECONDS)) {
                throw new IllegalStateException("the test never released the read");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        }
        if (failure != null) {
            throw failure;
        }
        Integer next = masks.poll();
        return next == null ? 0 : next;
    }

    @Override
    public boolean getSingleBumper(int bumperNumber) {
        return (getAllBumper() & 1 << bumperNumber - 1) != 0;
    }
}
