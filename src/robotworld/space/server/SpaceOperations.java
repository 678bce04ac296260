package robotworld.space.server;

import java.util.List;
import java.util.concurrent.TimeUnit;

import robotworld.space.ContainerInfo;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.Entry;
import robotworld.space.Operation;
import robotworld.space.Removal;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Subscription;
import robotworld.space.Timeout;
import robotworld.space.wire.WireError;
import robotworld.space.wire.WireWriter;

/**
 * The operations of the wire protocol, each run against the space with the request's fields and answered into a
 * writer. Waiting operations wait at most the server's maximum per request: a longer (or infinite) timeout gets
 * {@code {"more": true}} when that runs out, and the client asks again with what is left of its timeout.
 */
final class SpaceOperations {

    private final ServerState state;

    SpaceOperations(ServerState state) {
        this.state = state;
    }

    /** Runs operation {@code name}; false if there is no such operation. */
    boolean run(String name, RequestFields in, WireWriter out) {
        switch (name) {
            case "create" -> out.cref("container", state.space.createContainer(in.required(in.spec, "spec")));
            case "lookup" -> out.cref("container", state.space.lookupContainer(in.required(in.name, "name")));
            case "lookupOrCreate" -> out.cref("container",
                    state.space.lookupOrCreateContainer(in.required(in.spec, "spec")));
            case "destroyContainer" -> state.space.destroyContainer(in.required(in.container, "container"));
            case "describe" -> describe(in, out);
            case "read" -> waiting(Operation.READ, in, out);
            case "take" -> waiting(Operation.TAKE, in, out);
            case "destroy" -> waiting(Operation.DESTROY, in, out);
            case "write" -> waiting(Operation.WRITE, in, out);
            case "writeThenTake" -> putThenTake(false, in, out);
            case "shiftThenTake" -> putThenTake(true, in, out);
            case "shift" -> shift(in, out);
            case "ack" -> in.required(in.calls, "calls").forEach(state.leases::acknowledge);
            case "cancel" -> cancel(in.required(in.call, "call"), out);
            case "subscribe" -> subscribe(in, out);
            case "unsubscribe" -> unsubscribe(in);
            case "endSession" -> endSession(in);
            default -> {
                return false;
            }
        }
        return true;
    }

    /**
     * A write or shift may have handed entries to calls waiting on other servlet threads. Giving up the CPU here
     * lets such a call answer its client before this one finishes its own answer: on a machine with few cores
     * that takes the thread switch off the critical path of a request/answer exchange (about 25 µs of ~190 µs on
     * the 2-core test VM; see docs/benchmarks.md). With nothing else runnable it returns at once.
     */
    private static void letWokenCallsRunFirst() {
        Thread.yield();
    }

    private void describe(RequestFields in, WireWriter out) {
        ContainerInfo info = state.space.describeContainer(in.required(in.container, "container"));
        out.cref("container", info.ref())
                .spec("spec", info.spec())
                .field("size", info.size())
                .field("blocked", info.blocked())
                .field("subscriptions", info.subscriptions());
    }

    // ---- waiting operations ----

    private void waiting(Operation operation, RequestFields in, WireWriter out) {
        waiting(operation, in, in.required(in.timeout, "timeout"), state.options.maxWaitMillis(), out);
    }

    /**
     * Runs a read, take, destroy or write that may wait, at most {@code maxWait} ms here.
     *
     * @return false if the wait ran out before the requested timeout ({@code "more"} was answered: no effect)
     */
    private boolean waiting(Operation operation, RequestFields in, Timeout requested, long maxWait, WireWriter out) {
        ContainerRef container = in.required(in.container, "container");
        if (operation == Operation.WRITE) {
            in.required(in.items, "items");
        }
        boolean split = requested.isInfinite() || requested.millis() > maxWait;
        Timeout wait = split ? Timeout.ofMillis(maxWait) : requested;
        boolean blocks = !wait.isTryOnce();
        if (!blocks && in.call != null && state.calls.isForbidden(in.call)) {
            throw new ErrorAnswer(WireError.CANCELLED, "call " + in.call + " was cancelled");
        }
        if (blocks && !state.waitingPermits.tryAcquire()) {
            return tryOnceOrBusy(operation, in, out);
        }
        try {
            CallRegistry.InFlight call = null;
            if (blocks) {
                // calls without an id are registered too, so that a stopping server can end their wait
                call = state.calls.begin(in.call != null ? in.call : state.calls.anonymousId());
                if (call == null) {
                    throw new ErrorAnswer(WireError.CANCELLED, "call " + in.call + " was cancelled");
                }
            }
            Object result = null;
            boolean timedOut = false;
            boolean interrupted = false;
            try {
                result = execute(operation, container, wait, in);
            } catch (SpaceTimeoutException e) {
                if (!split) {
                    finishQuietly(call);
                    throw e;
                }
                timedOut = true;
            } catch (SpaceInterruptedException e) {
                interrupted = true;
            } catch (RuntimeException e) {
                finishQuietly(call);
                throw e;
            }
            boolean cancelled = call != null && state.calls.finish(call);
            if (cancelled || interrupted) {
                if (result instanceof Removal removal) {
                    removal.restore();
                }
                boolean wroteAnyway = operation == Operation.WRITE && result != null;
                if (call != null) {
                    state.calls.done(call, wroteAnyway);
                }
                if (!wroteAnyway) {
                    throw state.stopping
                            ? new ErrorAnswer(WireError.STOPPING, "the server is stopping; the operation had no effect")
                            : new ErrorAnswer(WireError.CANCELLED, "the call was cancelled; it had no effect");
                }
            } else if (call != null) {
                state.calls.done(call, operation == Operation.WRITE && result != null);
            } else if (operation == Operation.WRITE && in.call != null) {
                state.receipts.writeCompleted(in.call); // so a client whose answer is lost can learn it happened
            }
            if (timedOut) {
                out.field("more", true);
                return false;
            }
            answer(operation, result, in.call, out);
            return true;
        } finally {
            if (blocks) {
                state.waitingPermits.release();
            }
        }
    }

    /**
     * Every place for a waiting operation is taken. An operation that can complete at once still does: the places
     * are usually held by calls waiting for answers, and the operations that produce those answers (a provider
     * taking the next request) must never be refused for that. Only an operation that would have to wait is told
     * to come back ({@code busy}).
     */
    private boolean tryOnceOrBusy(Operation operation, RequestFields in, WireWriter out) {
        try {
            return waiting(operation, in, Timeout.TRY_ONCE, 0, out);
        } catch (SpaceTimeoutException mustWait) {
            throw new ErrorAnswer(WireError.BUSY, "too many operations are waiting on this server; try again");
        }
    }

    /**
     * A write (or shift), then a take (from the same or another container) by the same thread: the two operations
     * one after the other, as if sent as two requests, but in one exchange, so a caller that waits for an answer to
     * what it writes has its take registered without a second round trip. Each operation is atomic on its own; the pair
     * is not (others may act between them). Both waits together stay within the server's maximum wait: if the
     * write cannot happen in it, the answer is {@code "more"} (nothing happened); once it has happened, the answer
     * says {@code "written": true}, also with {@code "more"} (the take's wait ran out: ask again with a plain take)
     * and with an error (the take failed; the write stays done).
     */
    private void putThenTake(boolean shift, RequestFields in, WireWriter out) {
        long started = System.nanoTime();
        RequestFields take = in.required(in.take, "take");
        take.required(take.container, "take.container");
        Timeout requested = in.required(in.timeout, "timeout");
        long maxWait = state.options.maxWaitMillis();
        if (shift) {
            shift(in, out); // never waits
        } else if (!waiting(Operation.WRITE, in, requested, maxWait, out)) {
            return; // "more": the write did not happen
        }
        out.field("written", true);
        long elapsed = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
        Timeout left = requested.isInfinite() || requested.isTryOnce() ? requested
                : Timeout.ofMillis(Math.max(0, requested.millis() - elapsed));
        try {
            waiting(Operation.TAKE, take, left, Math.max(0, maxWait - elapsed), out);
        } catch (ErrorAnswer e) {
            throw new ErrorAnswer(e.error, e.getMessage(), true);
        } catch (RuntimeException e) {
            throw new ErrorAnswer(WireError.of(e), e.getMessage() == null ? e.toString() : e.getMessage(), true);
        }
    }

    private void finishQuietly(CallRegistry.InFlight call) {
        if (call != null) {
            state.calls.finish(call);
            state.calls.done(call, false);
        }
    }

    private Object execute(Operation operation, ContainerRef container, Timeout wait, RequestFields in) {
        return switch (operation) {
            case READ -> state.space.read(container, wait, in.selectors);
            case TAKE, DESTROY -> state.space.removeWithReceipt(container, operation, wait, in.selectors);
            case WRITE -> {
                state.space.write(container, wait, in.items);
                letWokenCallsRunFirst();
                yield Boolean.TRUE;
            }
            default -> throw new IllegalStateException(operation.toString());
        };
    }

    @SuppressWarnings("unchecked")
    private void answer(Operation operation, Object result, String callId, WireWriter out) {
        List<Entry> entries;
        if (result instanceof Removal removal) {
            entries = removal.entries();
            if (callId != null && !entries.isEmpty()) {
                state.leases.hold(callId, removal, state.options.leaseMillis());
                out.field("ack", true);
            }
        } else if (result instanceof List<?> list) {
            entries = (List<Entry>) list;
        } else {
            return; // a write: the empty object says it is done
        }
        if (operation == Operation.DESTROY) {
            out.field("count", entries.size());
        } else {
            out.entries("entries", entries);
        }
    }

    private void shift(RequestFields in, WireWriter out) {
        if (in.call != null && state.calls.isForbidden(in.call)) {
            throw new ErrorAnswer(WireError.CANCELLED, "call " + in.call + " was cancelled");
        }
        List<Entry> displaced = state.space.shift(in.required(in.container, "container"),
                in.required(in.timeout, "timeout"), in.required(in.items, "items"));
        if (in.call != null) {
            state.receipts.completed(in.call, displaced); // a client whose answer is lost can ask
        }
        letWokenCallsRunFirst();
        out.entries("displaced", displaced);
    }

    /**
     * Cancels a call: stops it if it waits, undoes a take whose answer may not have arrived, reports a write or
     * shift that happened (with what the shift displaced), and otherwise makes sure the call never runs.
     */
    private void cancel(String callId, WireWriter out) {
        CallRegistry.Outcome outcome = state.calls.cancelRunning(callId);
        List<Entry> displaced = state.receipts.takeCompleted(callId);
        if (outcome == null) {
            if (state.leases.restore(callId)) {
                outcome = CallRegistry.Outcome.CANCELLED;
            } else if (displaced != null) {
                outcome = CallRegistry.Outcome.COMPLETED;
            } else {
                state.calls.forbid(callId);
                outcome = CallRegistry.Outcome.CANCELLED;
            }
        }
        if (outcome == CallRegistry.Outcome.COMPLETED) {
            out.field("outcome", "completed").entries("displaced", displaced == null ? List.of() : displaced);
        } else {
            out.field("outcome", "cancelled");
        }
    }

    // ---- notifications ----

    private void subscribe(RequestFields in, WireWriter out) {
        ContainerRef container = in.required(in.container, "container");
        EventSession session = state.sessions.get(in.required(in.session, "session"));
        if (session == null || session.isClosing()) {
            throw new ErrorAnswer(WireError.NO_SESSION, "no notification stream is connected for session "
                    + in.session);
        }
        if (session.forwarders().size() >= state.options.maxSubscriptionsPerSession()) {
            throw new ErrorAnswer(WireError.BUSY, "too many subscriptions in this session");
        }
        Forwarder forwarder = new Forwarder(session.nextSubscriptionId(), container, session, state.wire);
        session.add(forwarder);
        try {
            Subscription subscription = state.space.subscribe(container, in.required(in.operations, "operations"),
                    in.required(in.mode, "mode"), in.required(in.timeout, "timeout"), forwarder);
            forwarder.started(subscription);
        } catch (RuntimeException e) {
            session.ended(forwarder, null);
            throw e;
        }
        long sequence;
        try {
            sequence = state.space.sequence(container);
        } catch (ContainerNotFoundException destroyedMeanwhile) {
            sequence = -1; // the stream reports the end
        }
        out.field("subscription", forwarder.id).field("sequence", sequence);
    }

    private void endSession(RequestFields in) {
        EventSession session = state.sessions.get(in.required(in.session, "session"));
        if (session != null) {
            state.sessions.close(session);
        }
    }

    private void unsubscribe(RequestFields in) {
        EventSession session = state.sessions.get(in.required(in.session, "session"));
        if (session == null) {
            return; // its subscriptions ended with its stream
        }
        Forwarder forwarder = session.forwarder(in.required(in.subscription, "subscription"));
        if (forwarder != null) {
            forwarder.cancel();
        }
    }
}
