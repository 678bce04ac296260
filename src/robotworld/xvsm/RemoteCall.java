package robotworld.xvsm;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import robotworld.space.AsyncTakes;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Template;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/**
 * One remote call: write the request {@code <host#call, args..., function>} to REQUEST, take the answer under
 * the same key from ANSWER, both within one deadline. The key is unique to this call (see
 * {@link XVSMRuntime#nextCallKey()}), so the answer taken can only be this call's: never one meant for an
 * earlier call that timed out, nor for another thread of the same host.
 *
 * <p>When the deadline passes, the request is withdrawn from the queue if it is still there (so a late module
 * host does not carry out a command its caller gave up on); if it is already being served, the call is handed to
 * {@link AbandonedCalls}, which takes the late answer away. The withdrawal never holds the caller past the call's
 * bound: it gets {@value #WITHDRAW_MILLIS} ms, and none if the space itself answered late (a cluster taking its
 * partitions back, a slow link); what it cannot settle in that time goes to {@link AbandonedCalls} too, which
 * withdraws the request when it finds it queued.
 */
final class RemoteCall {

    /** How long the caller waits for its request to be withdrawn after the deadline. */
    static final long WITHDRAW_MILLIS = 250;
    /** A timeout answer later than this past the deadline says the space is slow: withdraw in the background. */
    private static final long LATE_ANSWER_NANOS = TimeUnit.MILLISECONDS.toNanos(100);

    private final XVSMRemoteModule module;
    private final CallTuple request;
    private final String function;
    private final long timeoutMillis;

    RemoteCall(XVSMRemoteModule module, CallTuple request, String function, long timeoutMillis) {
        this.module = module;
        this.request = request;
        this.function = function;
        this.timeoutMillis = timeoutMillis;
    }

    /** Runs the call; returns the answer, or throws what the answer or the missing answer means. */
    CallTuple run() {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
        ModuleContainers containers = module.containers;
        Tuple tuple = request.toTuple();
        List<Entry> answer;
        try {
            // one exchange with a remote space: the take of the answer waits there from the moment of the write
            answer = containers.writeThenTake(Item.of(tuple), () -> remaining(deadline), Selector.key(request.key()));
        } catch (SpaceTimeoutException e) {
            // a space that was late to say so is slow: the withdrawal starts, but the caller does not wait for it
            throw timedOut(giveUp(tuple, System.nanoTime() - deadline > LATE_ANSWER_NANOS ? 0 : WITHDRAW_MILLIS));
        } catch (SpaceInterruptedException e) {
            giveUp(tuple, WITHDRAW_MILLIS);
            throw failure("the calling thread was interrupted", e);
        } catch (SpaceException e) {
            // the space itself failed: asking it to withdraw the request now would spend a second network
            // allowance past the call's bound; the sweeper withdraws it (or its late answer) when it can
            abandon(tuple);
            throw failure("the space failed: " + e.getMessage(), e);
        }
        return decode(answer.get(0));
    }

    /** Only writes the request (for quiet functions); within the call timeout. */
    void send() {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
        ModuleContainers containers = module.containers;
        try {
            containers.onRequests(requests -> {
                containers.space().write(requests, remaining(deadline), request.toTuple());
                return null;
            });
        } catch (SpaceInterruptedException e) {
            throw failure("the calling thread was interrupted", e);
        } catch (SpaceException e) {
            throw failure("cannot send the request: " + e.getMessage(), e);
        }
    }

    private CallTuple decode(Entry entry) {
        CallTuple answer;
        try {
            answer = CallTuple.parse(entry);
            if (ErrorAnswer.isError(answer)) {
                throw ErrorAnswer.parse(answer).toException(module.participant(), module.moduleName(), function);
            }
        } catch (MalformedCallException e) {
            throw failure("malformed answer: " + e.getMessage(), e);
        }
        if (!answer.key().equals(request.key()) || !answer.function().equals(request.function())) {
            throw failure("the answer " + answer + " does not belong to the request " + request, null);
        }
        return answer;
    }

    private ModuleCallTimeoutException timedOut(Withdrawal withdrawal) {
        return new ModuleCallTimeoutException(module.participant(), module.moduleName(), function, timeoutMillis,
                where() + ": no answer within " + timeoutMillis + " ms from the host serving it (asked from host "
                        + module.hostName() + "); " + switch (withdrawal) {
                            case WITHDRAWN -> "the request was still queued and is withdrawn: is the module's "
                                    + "program running?";
                            case BEING_SERVED -> "the request was being served; its late answer will be discarded";
                            case IN_BACKGROUND -> "the space was slow to answer; the request is withdrawn, or its "
                                    + "late answer discarded, in the background";
                        });
    }

    /** What became of a request whose call gave up. */
    private enum Withdrawal {
        /** Taken back from REQUEST before anyone served it. */
        WITHDRAWN,
        /** Already gone from REQUEST: being served; {@link AbandonedCalls} takes its late answer away. */
        BEING_SERVED,
        /** Not known in time: {@link AbandonedCalls} withdraws it, or takes its late answer away. */
        IN_BACKGROUND
    }

    private ModuleCallException failure(String why, Throwable cause) {
        return new ModuleCallException(module.participant(), module.moduleName(), function,
                where() + " (from host " + module.hostName() + "): " + why, cause);
    }

    /**
     * Withdraws the request if it is still queued, else leaves the late answer to {@link AbandonedCalls}; waits
     * at most {@code waitMillis} for the space. A withdrawal that takes longer goes on without the caller, and the
     * call is handed to {@link AbandonedCalls} at once (so that a runtime closing meanwhile still withdraws the
     * request); if the withdrawal then succeeds, the call is forgotten there.
     */
    private Withdrawal giveUp(Tuple tuple, long waitMillis) {
        boolean interrupted = Thread.interrupted(); // the clean-up must not fail for the caller's interrupt
        ModuleContainers containers = module.containers;
        CompletableFuture<Boolean> withdrawn = new CompletableFuture<>();
        try {
            AsyncTakes.of(containers.space()).takeLater(containers.requests(), Timeout.TRY_ONCE,
                    new Selector[] {Selector.template(Template.value(tuple), Selector.ALL)},
                    new SpaceEngine.Completion<>() {
                        @Override
                        public void completed(List<Entry> taken) {
                            withdrawn.complete(!taken.isEmpty());
                        }

                        @Override
                        public void failed(SpaceException failure) {
                            withdrawn.complete(false); // unknown: the sweeper looks again
                        }
                    });
            if (withdrawn.get(waitMillis, TimeUnit.MILLISECONDS)) {
                return Withdrawal.WITHDRAWN;
            }
        } catch (TimeoutException | InterruptedException stillRunning) {
            interrupted |= stillRunning instanceof InterruptedException;
            abandon(tuple);
            withdrawn.thenAccept(gone -> {
                if (gone) {
                    module.runtime().abandonedCalls().forget(request.key()); // nothing left to tidy up
                }
            });
            return Withdrawal.IN_BACKGROUND;
        } catch (SpaceException | ExecutionException e) {
            // unknown: let the sweeper look again
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
        abandon(tuple);
        return Withdrawal.BEING_SERVED;
    }

    /** Leaves the request, or its late answer, to {@link AbandonedCalls}. */
    private void abandon(Tuple tuple) {
        module.runtime().abandonedCalls().add(module.containers, request.key(), tuple);
    }

    private String where() {
        return module.participant() + "/" + module.moduleName() + " " + function;
    }

    private static Timeout remaining(long deadline) {
        return Timeout.ofMillis(Math.max(0, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
    }
}
