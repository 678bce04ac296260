package robotworld.space.server;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The blocking calls in progress, by the id their client gave them, so that a client can cancel a call it no
 * longer waits for (its thread was interrupted) and the server can cancel all of them when it stops.
 *
 * <p>Cancelling interrupts the thread that waits inside the space, and only while it does: the interrupt is
 * set and cleared under the call's monitor, so it never leaks into the servlet container. A cancel that
 * arrives before its call is remembered for a while, so the late call is refused instead of taking effect.
 */
final class CallRegistry {

    /** How long an early cancel is remembered, and how many at most. */
    private static final long TOMBSTONE_NANOS = TimeUnit.SECONDS.toNanos(60);
    private static final int MAX_TOMBSTONES = 10_000;

    private final Map<String, InFlight> running = new ConcurrentHashMap<>();
    private final java.util.concurrent.atomic.AtomicLong anonymous = new java.util.concurrent.atomic.AtomicLong();
    private final Map<String, Long> tombstones = new LinkedHashMap<>();
    /** Recent writes that happened, kept with the space, so a late cancel can be told that they happened. */
    private final SpaceReceipts receipts;

    CallRegistry(SpaceReceipts receipts) {
        this.receipts = receipts;
    }

    /** An id for a call whose client gave none (it cannot cancel it, but the server can). */
    String anonymousId() {
        return "~" + anonymous.incrementAndGet();
    }

    /** Registers a call; null if it was cancelled before it arrived. */
    InFlight begin(String id) {
        synchronized (tombstones) {
            if (tombstones.remove(id) != null) {
                return null;
            }
        }
        InFlight call = new InFlight(id, Thread.currentThread());
        if (running.putIfAbsent(id, call) != null) {
            throw new IllegalArgumentException("call id '" + id + "' is already in use");
        }
        return call;
    }

    /**
     * Ends a call's wait: after this, nothing interrupts its thread. Clears an interrupt a cancel left behind.
     *
     * @return whether the call was cancelled (its effect, if any, must be undone)
     */
    boolean finish(InFlight call) {
        boolean cancelled;
        synchronized (call) {
            cancelled = call.state == State.CANCELLED;
            call.state = State.FINISHED;
            Thread.interrupted();
        }
        return cancelled;
    }

    /**
     * Unregisters a call once its answer is decided (after any undo), releasing a cancel waiting for it.
     *
     * @param tookEffect whether the call changed the space for good (a write that happened)
     */
    void done(InFlight call, boolean tookEffect) {
        call.tookEffect = tookEffect;
        if (tookEffect && !call.id.startsWith("~")) {
            receipts.writeCompleted(call.id);
        }
        running.remove(call.id, call);
        call.settled.countDown();
    }

    /**
     * Cancels the call {@code id} if it still runs: interrupts its wait and waits (bounded) until it has settled.
     *
     * @return {@link Outcome#COMPLETED} if the call took effect anyway (a write that had just happened),
     *         {@link Outcome#CANCELLED} if it had no effect, null if no such call is running
     */
    Outcome cancelRunning(String id) {
        InFlight call = running.get(id);
        if (call == null) {
            return null;
        }
        interrupt(call);
        try {
            call.settled.await(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return call.tookEffect ? Outcome.COMPLETED : Outcome.CANCELLED;
    }

    /** Whether {@code id} was cancelled before it arrived; forgets the cancel. */
    boolean isForbidden(String id) {
        synchronized (tombstones) {
            return !tombstones.isEmpty() && tombstones.remove(id) != null;
        }
    }

    /** Makes sure a call that has not arrived (it may still be on its way) never runs. */
    void forbid(String id) {
        remember(id);
    }

    /** What a cancelled call did. */
    enum Outcome { CANCELLED, COMPLETED }

    /** Cancels every running call without waiting; used when the server stops. */
    void cancelAll() {
        for (InFlight call : running.values()) {
            interrupt(call);
        }
    }

    /** Waits (bounded) until no call runs any more. */
    void awaitIdle(long timeoutNanos) throws InterruptedException {
        long deadline = System.nanoTime() + timeoutNanos;
        for (InFlight call : running.values()) {
            long left = deadline - System.nanoTime();
            if (left <= 0 || !call.settled.await(left, TimeUnit.NANOSECONDS)) {
                return;
            }
        }
    }

    int size() {
        return running.size();
    }

    private static void interrupt(InFlight call) {
        synchronized (call) {
            if (call.state == State.RUNNING) {
                call.state = State.CANCELLED;
                call.thread.interrupt();
            }
        }
    }

    private void remember(String id) {
        long now = System.nanoTime();
        synchronized (tombstones) {
            tombstones.values().removeIf(at -> now - at > TOMBSTONE_NANOS);
            if (tombstones.size() >= MAX_TOMBSTONES) {
                tombstones.remove(tombstones.keySet().iterator().next());
            }
            tombstones.put(id, now);
        }
    }

    private enum State { RUNNING, CANCELLED, FINISHED }

    /** One call in progress. */
    static final class InFlight {
        final String id;
        final Thread thread;
        final CountDownLatch settled = new CountDownLatch(1);
        State state = State.RUNNING;
        volatile boolean tookEffect;

        InFlight(String id, Thread thread) {
            this.id = id;
            this.thread = thread;
        }
    }
}
