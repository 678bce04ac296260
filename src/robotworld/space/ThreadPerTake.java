package robotworld.space;

import java.util.List;

/**
 * Waits without {@link AsyncTakes}: each take blocks a thread of its own, which a cancel interrupts. Only for
 * space connections other than the embedded and the remote one (see {@link AsyncTakes#of}).
 */
final class ThreadPerTake implements AsyncTakes {
    private final Capi space;

    ThreadPerTake(Capi space) {
        this.space = space;
    }

    @Override
    public SpaceEngine.Pending takeLater(ContainerRef container, Timeout timeout,
                                         Selector[] selectors, SpaceEngine.Completion<List<Entry>> done) {
        return run(() -> space.take(container, timeout, selectors), done);
    }

    @Override
    public SpaceEngine.Pending shiftThenTakeLater(ContainerRef shiftTo, List<Item> items,
                                                  ContainerRef takeFrom, Timeout timeout,
                                                  Selector[] selectors,
                                                  SpaceEngine.Completion<List<Entry>> done) {
        return run(() -> space.shiftThenTake(shiftTo, items, takeFrom, timeout, selectors), done);
    }

    private static SpaceEngine.Pending run(java.util.function.Supplier<List<Entry>> take,
                                           SpaceEngine.Completion<List<Entry>> done) {
        java.util.concurrent.atomic.AtomicBoolean cancelling = new java.util.concurrent.atomic.AtomicBoolean();
        java.util.concurrent.atomic.AtomicBoolean delivered = new java.util.concurrent.atomic.AtomicBoolean();
        Thread thread = new Thread(() -> {
            List<Entry> entries = null;
            SpaceException failure = null;
            try {
                entries = take.get();
            } catch (SpaceException e) {
                failure = e;
            } catch (RuntimeException e) {
                // not a failure the space names (a bug in a Capi): still an outcome, or the waiter would never hear
                failure = new SpaceException("the take failed: " + e, e);
            }
            if (cancelling.get() && failure instanceof SpaceInterruptedException) {
                return; // withdrawn: an interrupted take had no effect
            }
            delivered.set(true); // a take that happened despite the cancel is delivered, never lost
            if (failure != null) {
                done.failed(failure);
            } else {
                done.completed(entries);
            }
        }, "xvsm-serve-take");
        thread.setDaemon(true);
        thread.start();
        return () -> {
            cancelling.set(true);
            thread.interrupt();
            try {
                thread.join(10_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return !delivered.get();
        };
    }
}
