package robotworld.space.internal;

import java.util.concurrent.locks.Condition;

import robotworld.space.SpaceException;

/**
 * A blocked operation, queued on its container. Whoever changes the container retries it (oldest first) inside
 * the same critical section and, on success, hands it the result; so an operation's effect and the hand-over are
 * one atomic step, and an entry taken for a waiter can never be lost by a timeout racing with it.
 */
final class Waiter {

    final Attempt attempt;
    /** Whether success changes the container, so that other waiters may be retried after it. */
    final boolean mutates;
    final Condition wakeUp;
    Object result;
    SpaceException failure;
    boolean done;

    Waiter(Attempt attempt, boolean mutates, Condition wakeUp) {
        this.attempt = attempt;
        this.mutates = mutates;
        this.wakeUp = wakeUp;
    }

    void succeed(Object value) {
        result = value;
        done = true;
        wakeUp.signal();
    }

    void fail(SpaceException error) {
        failure = error;
        done = true;
        wakeUp.signal();
    }

    /** One try of an operation against the current state: its result, or null if it must keep waiting. */
    @FunctionalInterface
    interface Attempt {
        Object tryOnce();
    }
}
