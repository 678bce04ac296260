package robotworld.space.server;

import java.net.InetAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import robotworld.space.ContainerInfo;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.Entry;
import robotworld.space.Operation;
import robotworld.space.Removal;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Subscription;
import robotworld.space.Timeout;
import robotworld.space.wire.BinaryWire;
import robotworld.space.wire.Wire;
import robotworld.space.wire.WireError;
import robotworld.space.wire.WireReader;
import robotworld.space.wire.WireWriter;

/**
 * The operations of the wire protocol, each run against the space with the request's fields and answered through
 * its {@link Exchange}. An operation that has to wait holds no thread: it waits in the space
 * ({@link SpaceEngine}), and its answer is sent from the thread that completes it, typically the request that
 * wrote the awaited entry. Waiting operations wait at most the server's maximum per request: a longer (or infinite)
 * timeout gets {@code {"more": true}} when that runs out, and the client asks again with what is left of its
 * timeout.
 */
final class SpaceOperations {

    private static final int MAX_ACKS_PER_REQUEST = 1024;

    private final ServerState state;

    SpaceOperations(ServerState state) {
        this.state = state;
    }

    /**
     * Runs one operation request: {@code acks} (take confirmations riding on it, comma-separated call ids, or null)
     * first, then operation {@code name} with its JSON {@code body}, answered through {@code exchange}. Failures
     * known at once are thrown.
     */
    void perform(String name, byte[] body, String acks, Exchange exchange) {
        acknowledge(acks);
        if (state.stopping && !name.equals("ack") && !name.equals("cancel")) {
            throw new ErrorAnswer(WireError.STOPPING, "the server is stopping; the operation had no effect");
        }
        if (body.length > 0 && body[0] == BinaryWire.MARKER) {
            if (!(exchange instanceof FrameExchange)) {
                throw new ErrorAnswer(WireError.BAD_REQUEST, "a binary body travels only in a frame; send JSON");
            }
            if (!BinaryWire.OPERATIONS.contains(name)) {
                throw new ErrorAnswer(WireError.BAD_REQUEST, "operation '" + Exchange.truncate(name, 40)
                        + "' is not carried in the binary form; send it as JSON");
            }
            exchange.answerInBinary();
        }
        RequestFields fields;
        try (WireReader in = state.wire.reader(body, 0, body.length)) {
            fields = RequestFields.parse(in, MAX_ACKS_PER_REQUEST);
        }
        if (!run(name, fields, exchange)) {
            throw new ErrorAnswer(WireError.NO_SUCH_ENDPOINT, "no operation '" + Exchange.truncate(name, 40) + "'");
        }
    }

    /** Acknowledgements of earlier takes ride on any request (an HTTP header, a frame field): comma-separated call ids. */
    private void acknowledge(String header) {
        if (header == null || header.isEmpty()) {
            return;
        }
        List<String> ids = new ArrayList<>();
        for (String token : header.split(",")) {
            if (ids.size() >= MAX_ACKS_PER_REQUEST) {
                throw new ErrorAnswer(WireError.BAD_REQUEST, "more than " + MAX_ACKS_PER_REQUEST + " acks in one request");
            }
            String[] reference = RequestFields.callReference(token.trim(), Wire.ACK_HEADER);
            if (reference[1] != null) {
                state.receipts.hint(reference[0], reference[1]);
            }
            ids.add(reference[0]);
        }
        state.receipts.acknowledge(ids);
    }

    /**
     * Runs operation {@code name} and answers it through {@code exchange}, at once or, for an operation that waits,
     * from the thread it completes on; false if there is no such operation. Failures known at once are thrown.
     */
    boolean run(String name, RequestFields in, Exchange exchange) {
        switch (name) {
            case "read" -> waiting(Operation.READ, in, exchange);
            case "take" -> waiting(Operation.TAKE, in, exchange);
            case "destroy" -> waiting(Operation.DESTROY, in, exchange);
            case "write" -> waiting(Operation.WRITE, in, exchange);
            case "writeThenTake" -> putThenTake(false, in, exchange);
            case "shiftThenTake" -> putThenTake(true, in, exchange);
            default -> {
                Exchange.Body body = exchange.body();
                if (!runAtOnce(name, in, body.out)) {
                    return false;
                }
                exchange.answer(body);
            }
        }
        return true;
    }

    /** The operations that never wait, answered into {@code out}; false if there is no such operation. */
    private boolean runAtOnce(String name, RequestFields in, WireWriter out) {
        switch (name) {
            case "create" -> out.cref("container", state.space.createContainer(in.required(in.spec, "spec")));
            case "lookup" -> out.cref("container", state.space.lookupContainer(in.required(in.name, "name")));
            case "lookupOrCreate" -> out.cref("container",
                    state.space.lookupOrCreateContainer(in.required(in.spec, "spec")));
            case "destroyContainer" -> state.space.destroyContainer(in.required(in.container, "container"));
            case "describe" -> describe(in, out);
            case "shift" -> shift(in, out);
            case "ack" -> {
                // the confirmations may all have come in the Space-Ack header (a client's background flush)
                List<String> calls = in.calls == null ? List.of() : in.calls;
                for (int i = 0; i < calls.size(); i++) {
                    hint(calls.get(i), in.callContainers.get(i));
                }
                state.receipts.acknowledge(calls);
            }
            case "cancel" -> {
                hint(in.required(in.call, "call"), in.callContainer);
                cancel(in.call, out);
            }
            case "subscribe" -> subscribe(in, out);
            case "unsubscribe" -> unsubscribe(in);
            case "endSession" -> endSession(in);
            default -> {
                return false;
            }
        }
        return true;
    }

    /** Tells the receipts where a client says its call ran, when it says so. */
    private void hint(String callId, String container) {
        if (container != null) {
            state.receipts.hint(callId, container);
        }
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

    /** What a waiting step hands on when the server's wait ran out before the requested timeout. */
    private static final Object MORE = new Object();

    /** Where the outcome of one waiting step goes: the next step, or the answer. */
    private interface Step {
        /** The operation happened with {@code result} (a Removal, entries, or TRUE for a write), or {@link #MORE}. */
        void done(Object result);

        /** It failed (without effect, except where an {@link ErrorAnswer} says {@code written}). */
        void failed(RuntimeException failure);
    }

    private void waiting(Operation operation, RequestFields in, Exchange exchange) {
        Exchange.Body body = exchange.body();
        waitFor(operation, in, in.required(in.timeout, "timeout"), state.options.maxWaitMillis(), exchange,
                new Step() {
                    @Override
                    public void done(Object result) {
                        if (result == MORE) {
                            body.out.field("more", true);
                        } else {
                            answer(operation, result, in.call, body.out);
                        }
                        exchange.answer(body);
                    }

                    @Override
                    public void failed(RuntimeException failure) {
                        exchange.fail(failure);
                    }
                });
    }

    /**
     * Runs a read, take, destroy or write that may wait, at most {@code maxWait} ms here, without holding a thread
     * while it waits: the space calls back when it completes. {@code step} gets the result, or {@link #MORE} when
     * the wait ran out before the requested timeout (no effect).
     */
    private void waitFor(Operation operation, RequestFields in, Timeout requested, long maxWait, Exchange exchange,
                         Step step) {
        ContainerRef container = in.required(in.container, "container");
        if (operation == Operation.WRITE) {
            in.required(in.items, "items");
        }
        boolean split = requested.isInfinite() || requested.millis() > maxWait;
        Timeout wait = split ? Timeout.ofMillis(maxWait) : requested;
        if (wait.isTryOnce()) {
            if (in.call != null && state.calls.isForbidden(in.call)) {
                throw new ErrorAnswer(WireError.CANCELLED, "call " + in.call + " was cancelled");
            }
            start(operation, container, wait, in, new SpaceEngine.Completion<>() {
                @Override
                public void completed(Object result) {
                    if (operation == Operation.WRITE && in.call != null) {
                        state.receipts.completed(in.call, List.of()); // so a client whose answer is lost can learn it
                    }
                    step.done(result);
                }

                @Override
                public void failed(SpaceException failure) {
                    if (split && failure instanceof SpaceTimeoutException) {
                        step.done(MORE);
                    } else {
                        step.failed(failure);
                    }
                }
            });
            return;
        }
        InetAddress client = exchange.client();
        String noPlace = state.enterWaiting(client);
        if (noPlace != null) {
            tryOnceOrBusy(operation, in, exchange, step, noPlace);
            return;
        }
        WaitingCall waiting = new WaitingCall(operation, split, step, client);
        // calls without an id are registered too, so that a stopping server can end their wait
        CallRegistry.InFlight call = state.calls.begin(in.call != null ? in.call : state.calls.anonymousId(),
                waiting::withdrawn);
        if (call == null) {
            state.leaveWaiting(client);
            throw new ErrorAnswer(WireError.CANCELLED, "call " + in.call + " was cancelled");
        }
        waiting.call = call;
        SpaceEngine.Pending pending;
        try {
            pending = start(operation, container, wait, in, waiting);
        } catch (RuntimeException e) {
            state.calls.finish(call);
            state.calls.done(call, false);
            state.leaveWaiting(client);
            throw e;
        }
        state.calls.attach(call, pending);
    }

    /** A registered call waiting in the space: settles it when the space calls back, or when a cancel withdrew it. */
    private final class WaitingCall implements SpaceEngine.Completion<Object> {
        private final Operation operation;
        private final boolean split;
        private final Step step;
        private final InetAddress client;
        CallRegistry.InFlight call;

        WaitingCall(Operation operation, boolean split, Step step, InetAddress client) {
            this.operation = operation;
            this.split = split;
            this.step = step;
            this.client = client;
        }

        @Override
        public void completed(Object result) {
            boolean cancelled = state.calls.finish(call);
            boolean wrote = operation == Operation.WRITE;
            if (cancelled) {
                if (result instanceof Removal removal) {
                    removal.restore();
                }
                state.calls.done(call, wrote);
                state.leaveWaiting(client);
                if (!wrote) {
                    step.failed(noEffect());
                    return;
                }
            } else {
                state.calls.done(call, wrote);
                state.leaveWaiting(client);
            }
            step.done(result);
        }

        @Override
        public void failed(SpaceException failure) {
            boolean cancelled = state.calls.finish(call);
            state.calls.done(call, false);
            state.leaveWaiting(client);
            if (cancelled) {
                step.failed(noEffect());
            } else if (split && failure instanceof SpaceTimeoutException) {
                step.done(MORE);
            } else {
                step.failed(failure);
            }
        }

        /** A cancel withdrew the operation from the space: it had no effect. */
        void withdrawn() {
            state.calls.finish(call);
            state.calls.done(call, false);
            state.leaveWaiting(client);
            step.failed(noEffect());
        }

        private ErrorAnswer noEffect() {
            return state.stopping
                    ? new ErrorAnswer(WireError.STOPPING, "the server is stopping; the operation had no effect")
                    : new ErrorAnswer(WireError.CANCELLED, "the call was cancelled; it had no effect");
        }
    }

    /**
     * Every place for a waiting operation is taken (the server's, or its client's address's: {@code why}). An operation that can complete at once still does: the places
     * are usually held by calls waiting for answers, and the operations that produce those answers (a provider
     * taking the next request) must never be refused for that. Only an operation that would have to wait is told
     * to come back ({@code busy}).
     */
    private void tryOnceOrBusy(Operation operation, RequestFields in, Exchange exchange, Step step, String why) {
        waitFor(operation, in, Timeout.TRY_ONCE, 0, exchange, new Step() {
            @Override
            public void done(Object result) {
                step.done(result);
            }

            @Override
            public void failed(RuntimeException failure) {
                step.failed(failure instanceof SpaceTimeoutException
                        ? new ErrorAnswer(WireError.BUSY, why)
                        : failure);
            }
        });
    }

    /**
     * A write (or shift), then a take (from the same or another container): the two operations one after the
     * other, as if sent as two requests, but in one exchange, so a caller that waits for an answer to what it writes
     * has its take registered without a second round trip. Each operation is atomic on its own; the pair is not
     * (others may act between them). Both waits together stay within the server's maximum wait: if the write cannot
     * happen in it, the answer is {@code "more"} (nothing happened); once it has happened, the answer says
     * {@code "written": true}, also with {@code "more"} (the take's wait ran out: ask again with a plain take) and
     * with an error (the take failed; the write stays done).
     */
    private void putThenTake(boolean shift, RequestFields in, Exchange exchange) {
        long started = System.nanoTime();
        RequestFields take = in.required(in.take, "take");
        take.required(take.container, "take.container");
        Timeout requested = in.required(in.timeout, "timeout");
        long maxWait = state.options.maxWaitMillis();
        Exchange.Body body = exchange.body();
        Step takeStep = new Step() {
            @Override
            public void done(Object result) {
                if (result == MORE) {
                    body.out.field("more", true);
                } else {
                    answer(Operation.TAKE, result, take.call, body.out);
                }
                exchange.answer(body);
            }

            @Override
            public void failed(RuntimeException e) {
                if (e instanceof ErrorAnswer answer) {
                    exchange.fail(answer.error, answer.getMessage(), true);
                } else {
                    exchange.fail(WireError.of(e), e.getMessage() == null ? e.toString() : e.getMessage(), true);
                }
            }
        };
        Runnable thenTake = () -> {
            body.out.field("written", true);
            long elapsed = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            Timeout left = requested.isInfinite() || requested.isTryOnce() ? requested
                    : Timeout.ofMillis(Math.max(0, requested.millis() - elapsed));
            try {
                waitFor(Operation.TAKE, take, left, Math.max(0, maxWait - elapsed), exchange, takeStep);
            } catch (RuntimeException e) {
                takeStep.failed(e);
            }
        };
        if (shift) {
            shift(in, body.out); // never waits
            thenTake.run();
            return;
        }
        waitFor(Operation.WRITE, in, requested, maxWait, exchange, new Step() {
            @Override
            public void done(Object result) {
                if (result == MORE) {
                    body.out.field("more", true); // the write did not happen
                    exchange.answer(body);
                } else {
                    thenTake.run();
                }
            }

            @Override
            public void failed(RuntimeException failure) {
                exchange.fail(failure);
            }
        });
    }

    /** Starts an operation in the space; its outcome goes to {@code done} (a write completes with TRUE). */
    @SuppressWarnings("unchecked")
    private SpaceEngine.Pending start(Operation operation, ContainerRef container, Timeout wait, RequestFields in,
                                      SpaceEngine.Completion<Object> done) {
        return switch (operation) {
            case READ -> state.space.readLater(container, wait, in.selectors,
                    (SpaceEngine.Completion<List<Entry>>) (SpaceEngine.Completion<?>) done);
            case TAKE, DESTROY -> state.space.removeLater(container, operation, wait, in.selectors, in.call,
                    (SpaceEngine.Completion<Removal>) (SpaceEngine.Completion<?>) done);
            case WRITE -> state.space.writeLater(container, wait, in.items, in.call, new SpaceEngine.Completion<>() {
                @Override
                public void completed(Void nothing) {
                    done.completed(Boolean.TRUE);
                }

                @Override
                public void failed(SpaceException failure) {
                    done.failed(failure);
                }
            });
            default -> throw new IllegalStateException(operation.toString());
        };
    }

    @SuppressWarnings("unchecked")
    private void answer(Operation operation, Object result, String callId, WireWriter out) {
        List<Entry> entries;
        if (result instanceof Removal removal) {
            entries = removal.entries();
            if (callId != null && !entries.isEmpty()) {
                state.receipts.hold(callId, removal, state.options.leaseMillis());
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
        // the calls this shift completes are answered on this thread, inside the shift, before this answer
        List<Entry> displaced = state.space.shift(in.required(in.container, "container"),
                in.required(in.timeout, "timeout"), in.required(in.items, "items"), in.call);
        if (in.call != null) {
            state.receipts.completed(in.call, displaced); // a client whose answer is lost can ask
        }
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
            if (state.receipts.restore(callId)) {
                outcome = CallRegistry.Outcome.CANCELLED;
            } else if (displaced != null) {
                outcome = CallRegistry.Outcome.COMPLETED;
            } else {
                displaced = state.receipts.forbid(callId); // the space may find that it happened meanwhile
                outcome = displaced != null ? CallRegistry.Outcome.COMPLETED : CallRegistry.Outcome.CANCELLED;
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
