package robotworld.xvsm;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.Function;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.space.Capi;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.Timeout;

/**
 * The thread that serves one module's REQUEST container: a blocking take (or, with adaptive batching, first a
 * take of everything waiting), then the answers from the module, shifted into ANSWER under each requester's key
 * in one operation. Space failures are retried with a growing pause; the loop only ends on {@link #stop}, or
 * when the space is closed.
 *
 * <p>Stopping is clean: the thread is interrupted only while it waits (for requests, or in a pause), so a
 * request it has taken is always answered before it ends.
 */
final class RequestServer {

    private static final Logger LOG = LoggerFactory.getLogger(RequestServer.class);
    private static final Timeout ANSWER_TIMEOUT = Timeout.ofMillis(5_000);
    private static final long FIRST_PAUSE_MILLIS = 20;
    private static final long LONGEST_PAUSE_MILLIS = 2_000;
    private static final long JOIN_MILLIS = 10_000;

    /** Thrown inside the loop when it is to stop. */
    private static final class Stop extends Exception {
        Stop() {
            super(null, null, false, false);
        }
    }

    private final ModuleContainers containers;
    private final String name;
    private final Function<List<CallTuple>, List<CallTuple>> answerer;
    private final BooleanSupplier batching;
    private final Object lock = new Object();
    private Thread thread;
    private boolean stopping;
    private boolean waiting;

    /**
     * @param name     participant/module, for the thread's name and log messages
     * @param answerer the answers to a batch of requests, one per request in order; never throws
     * @param batching whether to take all waiting requests at once
     */
    RequestServer(ModuleContainers containers, String name, Function<List<CallTuple>, List<CallTuple>> answerer,
                  BooleanSupplier batching) {
        this.containers = containers;
        this.name = name;
        this.answerer = answerer;
        this.batching = batching;
    }

    void start() {
        synchronized (lock) {
            if (thread != null || stopping) {
                throw new IllegalStateException("the request server of " + name + " was already started");
            }
            thread = new Thread(this::run, "xvsm-serve " + name);
            thread.setDaemon(true);
            // the loop catches every exception; an Error (out of memory, say) must still not pass unseen
            thread.setUncaughtExceptionHandler((dead, error) -> LOG.error("{}: the serving thread died; the module is"
                    + " no longer served", name, error));
            thread.start();
        }
    }

    /** Whether the serving thread is alive. */
    boolean isRunning() {
        synchronized (lock) {
            return thread != null && thread.isAlive();
        }
    }

    /** Stops the loop, waits for the thread to end (after answering what it has taken); idempotent. */
    void stop() {
        Thread serving;
        synchronized (lock) {
            stopping = true;
            serving = thread;
            if (serving != null && waiting) {
                serving.interrupt();
            }
        }
        if (serving == null || serving == Thread.currentThread()) {
            return;
        }
        try {
            serving.join(JOIN_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (serving.isAlive()) {
            LOG.warn("{}: the serving thread is still busy with the hardware after {} ms; leaving it", name,
                    JOIN_MILLIS);
        }
    }

    private void run() {
        long pause = 0;
        List<CallTuple> taken = null; // requests taken together with the previous answers
        while (true) {
            try {
                List<CallTuple> requests = taken != null ? taken : nextRequests();
                taken = null;
                if (pause > 0) {
                    LOG.info("{}: serving again", name);
                    pause = 0;
                }
                if (!requests.isEmpty()) {
                    taken = answer(requests);
                }
            } catch (Stop | SpaceClosedException end) {
                return;
            } catch (RuntimeException e) {
                // the space failed or is unreachable, or anything else went wrong: this thread is the module's
                // only server, so it never ends for that; it tries again, more slowly, and says so once
                taken = null;
                if (pause == 0) {
                    LOG.warn("{}: cannot serve requests ({}); trying again with growing pauses up to {} ms", name,
                            e.toString(), LONGEST_PAUSE_MILLIS);
                } else {
                    LOG.debug("{}: still cannot serve requests ({})", name, e.toString());
                }
                pause = pause == 0 ? FIRST_PAUSE_MILLIS : Math.min(LONGEST_PAUSE_MILLIS, pause * 2);
                try {
                    pause(pause);
                } catch (Stop stop) {
                    return;
                }
            }
        }
    }

    private List<CallTuple> nextRequests() throws Stop {
        Capi space = containers.space();
        if (batching.getAsBoolean()) {
            checkStopping();
            List<Entry> waitingNow = containers.onRequests(requests -> space.take(requests, Timeout.TRY_ONCE,
                    Selector.fifo(Selector.ALL)));
            if (!waitingNow.isEmpty()) {
                return parse(waitingNow);
            }
        }
        return parse(whileWaiting(() -> containers.onRequests(requests -> space.take(requests, Timeout.INFINITE))));
    }

    /**
     * Delivers the answers to {@code requests}. Without batching, the same exchange with the space then waits for
     * the next request ({@link Capi#shiftThenTake}), which saves a round trip per request.
     *
     * @return the next requests, taken with the answers; null if they are still to be taken
     */
    private List<CallTuple> answer(List<CallTuple> requests) {
        List<CallTuple> answers = answerer.apply(requests);
        List<Item> items = new ArrayList<>(answers.size());
        for (CallTuple answer : answers) {
            items.add(Item.keyed(answer.key(), answer.toTuple()));
        }
        if (!batching.getAsBoolean()) {
            try {
                return parse(whileWaiting(() -> containers.space().shiftThenTake(containers.answers(), items,
                        containers.requests(), Timeout.INFINITE)));
            } catch (Stop | SpaceException e) {
                // stopping, or the space failed: whether the answers were delivered is unknown, so they are
                // delivered (again) below. Under the same keys that is harmless: a second shift displaces the first,
                // or leaves an answer its caller already has, which nobody takes.
            }
        }
        shift(items);
        return null;
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

    /** Runs a waiting operation that {@link #stop} may interrupt. */
    private <T> T whileWaiting(Supplier<T> operation) throws Stop {
        synchronized (lock) {
            if (stopping) {
                throw new Stop();
            }
            waiting = true;
        }
        try {
            return operation.get();
        } catch (SpaceInterruptedException e) {
            checkStopping();
            throw e;
        } finally {
            synchronized (lock) {
                waiting = false;
                // an interrupt from stop() that came just after the take succeeded: serve what was taken first
                Thread.interrupted();
            }
        }
    }

    private void pause(long millis) throws Stop {
        whileWaiting(() -> {
            try {
                Thread.sleep(millis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new SpaceInterruptedException("pause interrupted", e);
            }
            return null;
        });
    }

    private void checkStopping() throws Stop {
        synchronized (lock) {
            if (stopping) {
                throw new Stop();
            }
        }
    }
}
