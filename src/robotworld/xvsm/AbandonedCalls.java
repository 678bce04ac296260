package robotworld.xvsm;

import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import robotworld.space.Entry;
import robotworld.space.Selector;
import robotworld.space.SpaceException;
import robotworld.space.Template;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/**
 * Tidies up after remote calls that timed out while their request was already being served: the answer will
 * still arrive under the call's key, and nobody will take it. Each such call is remembered; every
 * {@value #SWEEP_MILLIS} ms the runtime's background thread takes its answer away if it has come, or withdraws
 * its request if it came back into the queue (a space server puts back a take its client never confirmed).
 * After {@value #GIVE_UP_MILLIS} ms a call is forgotten. Never on a caller's path.
 */
final class AbandonedCalls {

    static final long SWEEP_MILLIS = 200;
    static final long GIVE_UP_MILLIS = 60_000;

    /** One abandoned call: its module's containers, its key, its request. */
    private record Call(ModuleContainers containers, String key, Tuple request, long sinceNanos) {
    }

    private final Queue<Call> calls = new ConcurrentLinkedQueue<>();
    private final ScheduledExecutorService background;
    private final AtomicBoolean sweepScheduled = new AtomicBoolean();

    AbandonedCalls(ScheduledExecutorService background) {
        this.background = background;
    }

    /** Remembers a call whose answer may still come. */
    void add(ModuleContainers containers, String key, Tuple request) {
        calls.add(new Call(containers, key, request, System.nanoTime()));
        scheduleSweep();
    }

    /** Forgets the call with {@code key}: its request was withdrawn after all, so no answer will come. */
    void forget(String key) {
        calls.removeIf(call -> call.key().equals(key));
    }

    /** How many calls are still being tidied up after. */
    int size() {
        return calls.size();
    }

    /** One pass over all calls, on the caller's thread (for closing). */
    void sweepNow() {
        for (int n = calls.size(); n > 0; n--) {
            Call call = calls.poll();
            if (call == null) {
                return;
            }
            if (!tidied(call) && !expired(call)) {
                calls.add(call);
            }
        }
    }

    private void scheduleSweep() {
        if (sweepScheduled.compareAndSet(false, true)) {
            try {
                background.schedule(this::sweep, SWEEP_MILLIS, TimeUnit.MILLISECONDS);
            } catch (java.util.concurrent.RejectedExecutionException closing) {
                sweepScheduled.set(false);
            }
        }
    }

    private void sweep() {
        sweepScheduled.set(false);
        sweepNow();
        if (!calls.isEmpty()) {
            scheduleSweep();
        }
    }

    private static boolean tidied(Call call) {
        try {
            ModuleContainers containers = call.containers();
            List<Entry> answer = containers.onAnswers(answers -> containers.space().take(answers, Timeout.TRY_ONCE,
                    Selector.key(call.key(), Selector.ALL)));
            if (!answer.isEmpty()) {
                return true;
            }
            List<Entry> request = containers.onRequests(requests -> containers.space().take(requests,
                    Timeout.TRY_ONCE, Selector.template(Template.value(call.request()), Selector.ALL)));
            return !request.isEmpty();
        } catch (SpaceException e) {
            return false; // the space is unreachable or closed: try again later, or give up with the runtime
        }
    }

    private static boolean expired(Call call) {
        return System.nanoTime() - call.sinceNanos() > TimeUnit.MILLISECONDS.toNanos(GIVE_UP_MILLIS);
    }
}
