package robotworld.space.internal;

import java.util.concurrent.locks.Condition;

import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;

/**
 * A blocked operation, queued on its container. Whoever changes the container retries it (oldest first) inside
 * the same critical section and, on success, hands it the result; so an operation's effect and the hand-over are
 * one atomic step, and an entry taken for a waiter can never be lost by a timeout racing with it.
 *
 * <p>A waiter either has a waiting thread ({@link #wakeUp}, signalled) or, for an operation that waits without a
 * thread, a {@link #completion} that the container calls once its lock is released.
 */
final class Waiter {

    final Attempt attempt;
    /** Whether success changes the container, so that other waiters may be retried after it. */
    final boolean mutates;
    /** The waiting thread's condition; null for a waiter without a thread. */
    final Condition wakeUp;
    /** Where the outcome goes when no thread waits; null for a waiting thread. */
    final SpaceEngine.Completion<Object> completion;
    /** The key this waiter's only selector asks for (count 1), or null: then any change may unblock it. */
    final String key;
    /** The keys its success adds entries under (a write's keys), so that waiters for them are retried. */
    final java.util.Collection<String> adds;
    /** Its place in the queue: smaller is older. */
    long seq;
    /** The timeout of a waiter without a thread, if it has one. */
    WaitTimer.Timeout expiry;
    Object result;
    SpaceException failure;
    boolean done;

    Waiter(Attempt attempt, boolean mutates, Condition wakeUp, String key, java.util.Collection<String> adds) {
        this(attempt, mutates, wakeUp, null, key, adds);
    }

    Waiter(Attempt attempt, boolean mutates, Condition wakeUp, SpaceEngine.Completion<Object> completion, String key,
           java.util.Collection<String> adds) {
        this.attempt = attempt;
        this.mutates = mutates;
        this.wakeUp = wakeUp;
        this.completion = completion;
        this.key = key;
        this.adds = adds;
    }

    /** Records the result; a waiting thread is woken, a completion is left for the caller to run after unlocking. */
    void succeed(Object value) {
        result = value;
        settle();
    }

    void fail(SpaceException error) {
        failure = error;
        settle();
    }

    private void settle() {
        done = true;
        if (wakeUp != null) {
            wakeUp.signal();
        }
        if (expiry != null) {
            expiry.cancel();
        }
    }

    /** Calls the completion with the outcome; outside the container's lock. */
    void fire() {
        if (failure != null) {
            completion.failed(failure);
        } else {
            completion.completed(result);
        }
    }

    /** One try of an operation against the current state: its result, or null if it must keep waiting. */
    @FunctionalInterface
    interface Attempt {
        Object tryOnce();
    }
}
