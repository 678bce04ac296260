package robotworld.cluster;

import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

import robotworld.space.ContainerDestroyedException;
import robotworld.space.ContainerRef;
import robotworld.space.InvalidOperationException;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.Timeout;

/**
 * An operation queued in its container that waits without a thread: what a space server's waiting request is on a
 * cluster. A wake-up, a look now and then, its deadline, a cancel or its handle's closing each run one step (a
 * call to the container) on a pool thread, one step at a time; the completion is called exactly once, unless a
 * cancel withdrew the operation first.
 *
 * @param <T> what the completion receives
 */
final class AsyncWaiter<T> implements SpaceEngine.Pending {

    /** Builds the queuing call for a new call id and the time left (0 try once, -1 infinite). */
    @FunctionalInterface
    interface Request {
        ContainerCall build(OpId call, long waitMillis);
    }

    private enum State { WAITING, BUSY, FINISHED }

    /**
     * For tests: runs between registering a waiter and sending its queuing call, the window in which a wake-up
     * (a member leaving) used to queue an operation twice.
     */
    static volatile Runnable whileQueuing;

    private final ClusterSpace space;
    private final String container;
    private final ContainerRef ref;
    private final Timeout timeout;
    private final long deadline;
    private final Request request;
    private final Function<Outcome, T> result;
    private final SpaceEngine.Completion<T> done;
    private LocalWaiter waiter;
    private State state = State.WAITING;
    /** A wake-up came while a step ran: look again after it. */
    private boolean again;
    /** Why the waiter should give up as soon as the running step ends. */
    private SpaceException giveUp;
    private long nap = ClusterNode.FIRST_NAP_NANOS;
    private ScheduledFuture<?> look;
    private ScheduledFuture<?> expiry;
    private final WaiterStory story = WaiterStory.begin();

    AsyncWaiter(ClusterSpace space, String container, ContainerRef ref, Timeout timeout, Request request,
                Function<Outcome, T> result, SpaceEngine.Completion<T> done) {
        this.space = space;
        this.container = container;
        this.ref = ref;
        this.timeout = timeout;
        this.deadline = timeout.isInfinite() ? Long.MAX_VALUE
                : System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeout.millis());
        this.request = request;
        this.result = result;
        this.done = done;
    }

    /**
     * Queues the operation, on the calling thread. If it happens (or fails) at once, the completion is called
     * before this returns; failures known before any waiting are thrown.
     *
     * @return the handle to withdraw it
     */
    SpaceEngine.Pending start() {
        space.track(this);
        synchronized (this) {
            // a wake-up during the queuing call (a member leaving wakes every waiter) must wait for it: looking
            // before the container has the operation finds it unknown and would queue it a second time under the
            // same client call, and the container would then hold two removals for one call id
            state = State.BUSY;
        }
        Outcome outcome;
        try {
            outcome = queue();
        } catch (RuntimeException e) {
            end();
            throw e;
        }
        if (outcome.status != Outcome.Status.QUEUED) {
            finishWith(outcome);
            return SpaceEngine.Pending.DONE;
        }
        synchronized (this) {
            if (deadline != Long.MAX_VALUE) {
                expiry = space.node().schedule(() -> giveUp(new SpaceTimeoutException("timed out after " + timeout
                        + " on " + ref)), Math.max(0, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            }
        }
        rest(); // waits; looks at once if a wake-up (or a give-up) came during the queuing call
        return this;
    }

    /** Registers a new waiter and runs the queuing call; throws what is known at once. */
    private Outcome queue() {
        OpId call = space.node().begin();
        LocalWaiter registered = space.node().register(new LocalWaiter(call, this::woken));
        synchronized (this) {
            waiter = registered;
        }
        Runnable testHook = whileQueuing;
        if (testHook != null) {
            testHook.run();
        }
        long waitMillis = timeout.isInfinite() ? -1
                : Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime()));
        Outcome outcome;
        try {
            outcome = space.call(container, request.build(call, waitMillis));
        } catch (RuntimeException e) {
            space.node().unregister(registered);
            throw e;
        } finally {
            space.node().end(call);
        }
        if (outcome.status != Outcome.Status.QUEUED) {
            space.node().unregister(registered);
            if (outcome.status == Outcome.Status.INVALID) {
                throw new InvalidOperationException(outcome.message);
            }
            if (outcome.status == Outcome.Status.NOT_FOUND || outcome.status == Outcome.Status.DESTROYED) {
                throw new robotworld.space.ContainerNotFoundException("no container " + ref
                        + " (destroyed, or never created)");
            }
        }
        return outcome;
    }

    // ---- steps ----

    /** A wake-up (from the member whose call served it, a member leaving, or the handle closing). */
    private void woken() {
        story.woken();
        space.node().runStep(this::look);
    }

    private synchronized void scheduleLook() {
        if (look != null) {
            look.cancel(false);
        }
        look = space.node().schedule(this::look, TimeUnit.NANOSECONDS.toMillis(nap)); // in the background
        story.note("look again in ms", TimeUnit.NANOSECONDS.toMillis(nap));
        nap = Math.min(nap * 2, ClusterNode.LONGEST_NAP_NANOS);
    }

    /** Collects the result if the container has served the operation. */
    private void look() {
        synchronized (this) {
            if (state == State.BUSY) {
                again = true;
                return;
            }
            if (state == State.FINISHED) {
                return;
            }
            if (waiter.isClosed() && giveUp == null) {
                giveUp = space.node().isClosed() ? ClusterNode.memberGone(ref.space())
                        : new SpaceClosedException("the space handle was closed while waiting on " + ref);
            }
            state = State.BUSY;
        }
        if (giveUpIfAsked()) {
            return;
        }
        Outcome outcome;
        try {
            story.note("look", null);
            outcome = space.about(ContainerCall.Kind.COLLECT, container, waiter.id());
            story.note("found", outcome.status);
        } catch (SpaceUnavailableException recovering) {
            story.trouble("look failed:", recovering.getMessage());
            rest(); // the cluster is recovering: look again later
            return;
        } catch (SpaceException e) {
            finish(null, e);
            return;
        }
        switch (outcome.status) {
            case QUEUED -> rest();
            case UNKNOWN -> queueAgain();
            default -> finishWith(outcome);
        }
    }

    /** The container forgot the operation (this member was thought gone): it had no effect; queue it again. */
    private void queueAgain() {
        story.trouble("queue again", null);
        space.node().unregister(waiter);
        Outcome outcome;
        try {
            outcome = queue();
        } catch (SpaceUnavailableException recovering) {
            story.trouble("queue failed:", recovering.getMessage());
            rest();
            return;
        } catch (SpaceException e) {
            finish(null, e);
            return;
        }
        if (outcome.status == Outcome.Status.QUEUED) {
            rest();
        } else {
            finishWith(outcome);
        }
    }

    /** Back to waiting; runs what came in meanwhile. */
    private void rest() {
        boolean lookAgain;
        synchronized (this) {
            state = State.WAITING;
            lookAgain = again || giveUp != null;
            again = false;
            if (!lookAgain) {
                scheduleLook();
            }
            notifyAll();
        }
        if (lookAgain) {
            space.node().runStep(this::look);
        }
    }

    /** Its deadline passed, or its handle closed: withdraw it, unless it was served meanwhile. */
    void giveUp(SpaceException why) {
        synchronized (this) {
            if (state == State.FINISHED) {
                return;
            }
            giveUp = why;
            if (state == State.BUSY) {
                return; // the running step sees it
            }
            state = State.BUSY;
        }
        space.node().runStep(this::giveUpIfAsked);
    }

    /** Withdraws the operation if a give-up is pending (the caller holds the BUSY state); whether it did. */
    private boolean giveUpIfAsked() {
        SpaceException why;
        synchronized (this) {
            why = giveUp;
        }
        if (why == null) {
            return false;
        }
        Outcome outcome;
        try {
            outcome = space.about(ContainerCall.Kind.WITHDRAW, container, waiter.id());
        } catch (SpaceException e) {
            finish(null, e instanceof SpaceUnavailableException ? e : why);
            return true;
        }
        switch (outcome.status) {
            case WITHDRAWN, UNKNOWN -> finish(null, why);
            default -> finishWith(outcome); // served before it could be withdrawn: never lose that
        }
        return true;
    }

    /**
     * Withdraws the operation if it still waits (true: no effect, the completion is never called). May wait
     * briefly for a step in progress.
     */
    @Override
    public boolean cancel() {
        synchronized (this) {
            while (state == State.BUSY) {
                try {
                    wait();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return false;
                }
            }
            if (state == State.FINISHED) {
                return false;
            }
            state = State.BUSY;
        }
        Outcome outcome;
        try {
            outcome = space.about(ContainerCall.Kind.WITHDRAW, container, waiter.id());
        } catch (SpaceException e) {
            rest(); // not known whether it could be withdrawn: it goes on, and completes later
            return false;
        }
        if (outcome.status == Outcome.Status.WITHDRAWN || outcome.status == Outcome.Status.UNKNOWN) {
            end();
            return true;
        }
        finishWith(outcome);
        return false;
    }

    // ---- the end ----

    private void finishWith(Outcome outcome) {
        switch (outcome.status) {
            case DONE -> finish(result.apply(outcome), null);
            case NOT_POSSIBLE -> finish(null, new SpaceTimeoutException("not possible at once on " + ref));
            case INVALID -> finish(null, new InvalidOperationException(outcome.message));
            case DESTROYED, NOT_FOUND -> finish(null, new ContainerDestroyedException("container " + ref
                    + " was destroyed while waiting"));
            case CANCELLED -> finish(null, new robotworld.space.CallCancelledException(outcome.message));
            default -> finish(null, new SpaceException("the cluster failed a call on " + ref + ": "
                    + outcome.message));
        }
    }

    /** Ends the operation with {@code failure}, or else with its {@code value}. */
    private void finish(T value, SpaceException failure) {
        if (!end()) {
            return;
        }
        story.ended(ref, failure == null ? "its result" : failure);
        if (failure != null) {
            done.failed(failure);
        } else {
            done.completed(value);
        }
    }

    /** Ends the operation without calling its completion (a cancel withdrew it); false if it had ended already. */
    private boolean end() {
        synchronized (this) {
            if (state == State.FINISHED) {
                return false;
            }
            state = State.FINISHED;
            if (look != null) {
                look.cancel(false);
            }
            if (expiry != null) {
                expiry.cancel(false);
            }
            notifyAll();
        }
        if (waiter != null) {
            space.node().unregister(waiter);
        }
        space.untrack(this);
        return true;
    }
}
