package robotworld.xvsm;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Function;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.space.AsyncTakes;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.Timeout;

/**
 * Serves one module's REQUEST container, event-driven: while no request is there, the module waits in the space
 * without a thread (a take that completes later, {@link AsyncTakes}); when requests arrive, a thread of the
 * runtime's small {@link ServingThreads serving pool} answers them from the module (or, with adaptive batching,
 * first takes everything waiting), shifts the answers into ANSWER under each requester's key, and starts waiting
 * for the next request in the same exchange ({@link AsyncTakes#shiftThenTakeLater}). So a program serving a
 * thousand modules has a few threads, not a thousand, and the threads it has are the ones doing hardware calls.
 *
 * <p>Space failures, and any other exception met while serving, are retried with a growing pause (said once in
 * the log); serving only ends on {@link #stop}, when the space is closed, or on a {@link VirtualMachineError}. Stopping is clean: a waiting take is withdrawn (nothing it took is lost), and a request that was taken is
 * always answered before the server ends.
 *
 * <p>A space connection that cannot wait without a thread (another {@code Capi}) is served the same way, with
 * the take waiting on a thread of its own ({@link AsyncTakes#of}).
 */
final class RequestServer {

    private static final Logger LOG = LoggerFactory.getLogger(RequestServer.class);
    private static final Timeout ANSWER_TIMEOUT = Timeout.ofMillis(5_000);
    private static final long FIRST_PAUSE_MILLIS = 20;
    private static final long LONGEST_PAUSE_MILLIS = 2_000;
    private static final long JOIN_MILLIS = 10_000;
    private static final Selector[] NEXT_REQUEST = new Selector[0];

    private final ModuleContainers containers;
    private final String name;
    private final Function<List<CallTuple>, List<CallTuple>> answerer;
    private final BooleanSupplier batching;
    private final AsyncTakes takes;
    private final Object lock = new Object();
    private final CountDownLatch ended = new CountDownLatch(1);
    /** The take waiting in the space, or null while requests are worked on (or before start). */
    private SpaceEngine.Pending pending;
    private boolean started;
    private boolean stopping;
    private volatile boolean over;
    /** The thread working on requests right now, if any. */
    private volatile Thread worker;
    /** The current pause after space failures (0 while serving normally); serving thread only. */
    private long pause;

    /**
     * @param name     participant/module, for log messages
     * @param answerer the answers to a batch of requests, one per request in order; never throws
     * @param batching whether to take all waiting requests at once
     */
    RequestServer(ModuleContainers containers, String name, Function<List<CallTuple>, List<CallTuple>> answerer,
                  BooleanSupplier batching) {
        this.containers = containers;
        this.name = name;
        this.answerer = answerer;
        this.batching = batching;
        this.takes = AsyncTakes.of(containers.space());
    }

    void start() {
        synchronized (lock) {
            if (started || stopping) {
                throw new IllegalStateException("the request server of " + name + " was already started");
            }
            started = true;
        }
        ServingThreads.execute(() -> serve(null));
    }

    /** Whether the module is served: started, not stopped, and not ended by a fatal error. */
    boolean isRunning() {
        synchronized (lock) {
            return started && !over;
        }
    }

    /** Stops serving, waits until requests already taken are answered (at most 10 s); idempotent. */
    void stop() {
        SpaceEngine.Pending waiting;
        synchronized (lock) {
            if (stopping) {
                waiting = null;
            } else {
                stopping = true;
                waiting = pending;
                pending = null;
                if (!started) {
                    end();
                    return;
                }
            }
        }
        if (waiting != null && waiting.cancel()) {
            end(); // the take was withdrawn: nothing was taken, nothing to answer
            return;
        }
        if (worker == Thread.currentThread()) {
            return; // called from this module's own work: it ends when that returns
        }
        try {
            if (!ended.await(JOIN_MILLIS, TimeUnit.MILLISECONDS)) {
                LOG.warn("{}: still busy with the hardware after {} ms; leaving it", name, JOIN_MILLIS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void end() {
        over = true;
        ended.countDown();
    }

    /**
     * Starts waiting for the next requests, delivering {@code answers} first (in the same exchange unless batching).
     * On a serving thread.
     */
    private void serve(List<Item> answers) {
        List<Item> undelivered = answers;
        try {
            if (isStopping()) {
                if (answers != null) {
                    shift(answers);
                }
                end();
                return;
            }
            if (batching.getAsBoolean()) {
                if (answers != null) {
                    shift(answers);
                    undelivered = null;
                }
                List<Entry> waitingNow = containers.onRequests(requests -> containers.space().take(requests,
                        Timeout.TRY_ONCE, Selector.fifo(Selector.ALL)));
                if (!waitingNow.isEmpty()) {
                    ServingThreads.execute(() -> work(waitingNow)); // not work(): a busy module would recurse
                    return;
                }
                await(null);
            } else {
                await(answers);
            }
        } catch (SpaceClosedException closed) {
            end();
        } catch (RuntimeException e) {
            failed(e, undelivered);
        }
    }

    /** Starts the take (after a shift of {@code answers}, if any) that completes when a request arrives. */
    private void await(List<Item> answers) {
        Completion completion = new Completion(answers);
        SpaceEngine.Pending take = answers == null
                ? takes.takeLater(containers.requests(), Timeout.INFINITE, NEXT_REQUEST, completion)
                : takes.shiftThenTakeLater(containers.answers(), answers, containers.requests(), Timeout.INFINITE,
                        NEXT_REQUEST, completion);
        boolean withdraw;
        synchronized (lock) {
            withdraw = stopping && !completion.fired;
            if (!withdraw && !completion.fired) {
                pending = take;
            }
        }
        if (withdraw && take.cancel()) {
            end();
        }
    }

    /** Where the waiting take's outcome goes: straight on to a serving thread. */
    private final class Completion implements SpaceEngine.Completion<List<Entry>> {
        /** The answers shifted along with the take (their delivery is unknown if it fails). */
        private final List<Item> answers;
        /** Guarded by the server's lock. */
        boolean fired;

        Completion(List<Item> answers) {
            this.answers = answers;
        }

        private void fired() {
            synchronized (lock) {
                fired = true;
                pending = null;
            }
        }

        @Override
        public void completed(List<Entry> entries) {
            fired();
            ServingThreads.execute(() -> work(entries));
        }

        @Override
        public void failed(SpaceException failure) {
            fired();
            ServingThreads.execute(() -> RequestServer.this.failed(failure, answers));
        }
    }

    /** Answers what was taken and goes on waiting. On a serving thread. */
    private void work(List<Entry> entries) {
        worker = Thread.currentThread();
        List<Item> items;
        try {
            if (pause > 0) {
                LOG.info("{}: serving again", name);
                pause = 0;
            }
            List<CallTuple> requests = parse(entries);
            List<CallTuple> answers = requests.isEmpty() ? List.of() : answerer.apply(requests);
            items = new ArrayList<>(answers.size());
            for (CallTuple answer : answers) {
                items.add(Item.keyed(answer.key(), answer.toTuple()));
            }
        } catch (VirtualMachineError fatal) {
            LOG.error("{}: serving failed for good; the module is no longer served", name, fatal);
            end();
            throw fatal;
        } catch (RuntimeException bug) {
            // requests that cannot be answered (a failure of this runtime, not of the space): their callers time
            // out, and the module goes on being served, after a pause, like after a failure of the space
            worker = null;
            failed(bug, null);
            return;
        } finally {
            worker = null;
        }
        serve(items.isEmpty() ? null : items);
    }

    /**
     * The space failed or is unreachable: this is the module's only server, so it never gives up for that; it tries
     * again, more slowly, and says so once. Answers whose delivery is unknown are delivered (again): under the same
     * keys that is harmless (a second shift displaces the first, or leaves an answer its caller already has).
     */
    private void failed(RuntimeException failure, List<Item> undelivered) {
        try {
            retryLater(failure, undelivered);
        } catch (RuntimeException alsoFailed) {
            // whatever the clean-up met, the module is not left unserved
            LOG.warn("{}: recovering from a failure failed too ({}); trying again in {} ms", name, alsoFailed,
                    LONGEST_PAUSE_MILLIS, alsoFailed);
            pause = LONGEST_PAUSE_MILLIS;
            ServingThreads.schedule(() -> serve(null), LONGEST_PAUSE_MILLIS);
        }
    }

    /** A failure and what caused it, on one line (e.g. which network error made the space unreachable). */
    private static String withCauses(Throwable failure) {
        StringBuilder line = new StringBuilder(failure.toString());
        for (Throwable cause = failure.getCause(); cause != null && cause != cause.getCause();
                cause = cause.getCause()) {
            line.append(": ").append(cause);
        }
        return line.toString();
    }

    private void retryLater(RuntimeException failure, List<Item> undelivered) {
        if (failure instanceof SpaceClosedException || isStopping() && failure instanceof SpaceException) {
            if (undelivered != null) {
                shift(undelivered);
            }
            end();
            return;
        }
        if (failure instanceof ContainerNotFoundException) {
            try {
                containers.lookUpAgain(); // destroyed, or a server that came back empty
            } catch (RuntimeException stillDown) {
                // tried again after the pause
            }
        }
        if (undelivered != null) {
            shift(undelivered);
        }
        if (pause == 0 && failure instanceof SpaceException) {
            LOG.warn("{}: cannot serve requests ({}); trying again with growing pauses up to {} ms", name,
                    withCauses(failure), LONGEST_PAUSE_MILLIS);
        } else if (pause == 0) {
            // not the space: a fault of this program, with the trace to find it
            LOG.warn("{}: serving failed ({}); requests taken may go unanswered; trying again with growing pauses"
                    + " up to {} ms", name, failure.toString(), LONGEST_PAUSE_MILLIS, failure);
        } else {
            LOG.debug("{}: still cannot serve requests ({})", name, failure.toString());
        }
        pause = pause == 0 ? FIRST_PAUSE_MILLIS : Math.min(LONGEST_PAUSE_MILLIS, pause * 2);
        ServingThreads.schedule(() -> serve(null), pause);
    }

    private boolean isStopping() {
        synchronized (lock) {
            return stopping;
        }
    }

    private void shift(List<Item> items) {
        try {
            containers.onAnswers(answerContainer -> containers.space().shift(answerContainer, ANSWER_TIMEOUT, items));
        } catch (SpaceException e) {
            // the callers time out; nothing else to do with an answer that cannot be delivered
            LOG.warn("{}: cannot deliver {} answer(s): {}", name, items.size(), e.toString());
        }
    }

    private static List<CallTuple> parse(List<Entry> entries) {
        List<CallTuple> requests = new ArrayList<>(entries.size());
        for (Entry entry : entries) {
            try {
                requests.add(CallTuple.parse(entry));
            } catch (MalformedCallException e) {
                LOG.warn("ignoring a request nobody can be answered for: {}", e.getMessage());
            }
        }
        return requests;
    }
}
