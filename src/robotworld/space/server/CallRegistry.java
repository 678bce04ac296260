package robotworld.space.server;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import robotworld.space.CallReceipts;
import robotworld.space.SpaceEngine;

/**
 * The waiting calls in progress, by the id their client gave them, so that a client can cancel a call it no
 * longer waits for (its thread was interrupted) and the server can cancel all of them when it stops.
 *
 * <p>A waiting call holds no thread: it is an operation waiting in the space ({@link SpaceEngine.Pending}).
 * Cancelling withdraws it there; if it was withdrawn, the canceller answers its request ("cancelled" or
 * "stopping"), and if it had just completed, its completion sees the cancel and undoes what can be undone. A
 * cancel that arrives before its call is remembered for a while, so the late call is refused instead of taking
 * effect.
 */
final class CallRegistry {

    private final Map<String, InFlight> running = new ConcurrentHashMap<>();
    private final java.util.concurrent.atomic.AtomicLong anonymous = new java.util.concurrent.atomic.AtomicLong();
    /**
     * Recent writes that happened and calls cancelled before they arrived, kept with the space, so a late cancel can
     * be told that a write happened, and a late call refused.
     */
    private final CallReceipts receipts;

    CallRegistry(CallReceipts receipts) {
        this.receipts = receipts;
    }

    /** An id for a call whose client gave none (it cannot cancel it, but the server can). */
    String anonymousId() {
        return "~" + anonymous.incrementAndGet();
    }

    /**
     * Registers a call; null if it was cancelled before it arrived.
     *
     * @param onWithdrawn answers the call's request when a cancel withdrew its operation from the space
     */
    InFlight begin(String id, Runnable onWithdrawn) {
        if (receipts.isForbidden(id)) {
            return null;
        }
        InFlight call = new InFlight(id, onWithdrawn);
        if (running.putIfAbsent(id, call) != null) {
            throw new IllegalArgumentException("call id '" + id + "' is already in use");
        }
        return call;
    }

    /**
     * Hands a call the operation that waits for it in the space. If a cancel came first, the operation is withdrawn
     * at once (and the call answered as withdrawn), or, if it completed meanwhile, left to its completion.
     */
    void attach(InFlight call, SpaceEngine.Pending pending) {
        synchronized (call) {
            if (call.state != State.CANCELLED) {
                call.pending = pending;
                return;
            }
        }
        if (pending.cancel()) {
            call.onWithdrawn.run();
        }
    }

    /**
     * Ends a call's wait: its operation completed (or failed), and no cancel can withdraw it any more.
     *
     * @return whether the call was cancelled meanwhile (its effect, if any, must be undone)
     */
    boolean finish(InFlight call) {
        synchronized (call) {
            boolean cancelled = call.state == State.CANCELLED;
            call.state = State.FINISHED;
            return cancelled;
        }
    }

    /**
     * Unregisters a call once its answer is decided (after any undo), releasing a cancel waiting for it.
     *
     * @param tookEffect whether the call changed the space for good (a write that happened)
     */
    void done(InFlight call, boolean tookEffect) {
        call.tookEffect = tookEffect;
        if (tookEffect && !call.id.startsWith("~")) {
            receipts.completed(call.id, List.of());
        }
        running.remove(call.id, call);
        call.settled.countDown();
    }

    /**
     * Cancels the call {@code id} if it still runs: withdraws its wait and waits (bounded) until it has settled.
     *
     * @return {@link Outcome#COMPLETED} if the call took effect anyway (a write that had just happened),
     *         {@link Outcome#CANCELLED} if it had no effect, null if no such call is running
     */
    Outcome cancelRunning(String id) {
        InFlight call = running.get(id);
        if (call == null) {
            return null;
        }
        withdraw(call);
        try {
            call.settled.await(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return call.tookEffect ? Outcome.COMPLETED : Outcome.CANCELLED;
    }

    /** Whether {@code id} was cancelled before it arrived; forgets the cancel. */
    boolean isForbidden(String id) {
        return receipts.isForbidden(id);
    }

    /** What a cancelled call did. */
    enum Outcome { CANCELLED, COMPLETED }

    /** Cancels every running call without waiting; used when the server stops. */
    void cancelAll() {
        for (InFlight call : running.values()) {
            withdraw(call);
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

    /** Marks a running call cancelled and withdraws its operation; a withdrawn call is answered here. */
    private static void withdraw(InFlight call) {
        SpaceEngine.Pending pending;
        synchronized (call) {
            if (call.state != State.RUNNING) {
                return;
            }
            call.state = State.CANCELLED;
            pending = call.pending;
        }
        if (pending != null && pending.cancel()) {
            call.onWithdrawn.run();
        }
    }

    private enum State { RUNNING, CANCELLED, FINISHED }

    /** One call in progress. */
    static final class InFlight {
        final String id;
        final Runnable onWithdrawn;
        final CountDownLatch settled = new CountDownLatch(1);
        /** Guarded by this. */
        State state = State.RUNNING;
        /** The operation waiting in the space; guarded by this. */
        SpaceEngine.Pending pending;
        volatile boolean tookEffect;

        InFlight(String id, Runnable onWithdrawn) {
            this.id = id;
            this.onWithdrawn = onWithdrawn;
        }
    }
}
