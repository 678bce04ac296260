package robotworld.space.server;

import java.nio.channels.Selector;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.eclipse.jetty.io.ManagedSelector;

/**
 * The framed answers one selector thread produces while it works through the connections a {@code select()} found
 * ready, written together once it has been through all of them (before it selects again), as Redis writes its
 * replies before it waits for more.
 *
 * <p>Why: written at once, an answer reaches its client at a point of the round that depends on where its
 * connection (or the connection whose request completed its wait) happens to lie in the selector's key set, which
 * stays the same for a connection's life. So a request/answer pair could keep landing just after a round had
 * started and wait a whole round more on every call, while another pair always made the round it was sent for:
 * with 50 pairs, the most served made 2 to 5 times the calls of the least, and the least served made the tail.
 * Written at the end of the round, every answer of a round goes out together and every client's next request
 * competes for the same next round. For the same reason a connection answered at a round's end does not read on
 * there ({@link #atRoundEnd()}): its client's next request waits for the next {@code select()} with all the others.
 *
 * <p>A round whose {@code select()} found only one connection ready has no other client to be fair to: its answers
 * go out at once, so that their clients work while the selector thread finishes the request (a module call on two
 * CPUs took about 2 µs less that way, 4 %).
 *
 * <p>Contract: {@link #write} runs the write at once unless called on the thread that works through this
 * selector's rounds, inside one ({@link #enter} was called there for a connection of this selector) whose
 * {@code select()} found more than {@link #writeAtOnceUpTo} connections ready; then it runs at the round's end, on
 * that thread, in the order written. So an answer waits at most for the rest of the round it
 * was produced in: the end of a round is a Jetty selector update, run before the next {@code select()}, and queuing
 * it wakes nothing, since the selector is working then, not selecting. The thread that works a selector's
 * rounds is learnt from the updates themselves (Jetty may hand a selector to another thread); answers written on
 * any other thread (the space's timer, a pool thread) go out at once.
 */
final class AnswerRound implements ManagedSelector.SelectorUpdate {

    /** The round the current thread is working through, if it works a selector's rounds. */
    private static final ThreadLocal<AnswerRound> CURRENT = new ThreadLocal<>();
    private static final long RELEARN_NANOS = TimeUnit.SECONDS.toNanos(1);
    /** Up to how many ready connections a round writes its answers at once; tests set 0 to defer them all. */
    static volatile int writeAtOnceUpTo = 1;

    private final ManagedSelector selector;
    private final ConcurrentLinkedQueue<Runnable> writes = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean submitted = new AtomicBoolean();
    /** The thread that ran this selector's last update: the one working through its rounds. */
    private volatile Thread worker;
    /** The thread writing this round's answers at its end, while it does; only that thread reads it. */
    private Thread endingOn;
    /** How many connections the selector's last {@code select()} found ready; set and read by its worker. */
    private int ready;
    private volatile long learntAt;

    AnswerRound(ManagedSelector selector) {
        this.selector = selector;
        learn(); // run with the selector's first round: no wake-up, it has not started yet
    }

    /** A connection of this selector is being read on the current thread. */
    void enter() {
        Thread current = Thread.currentThread();
        if (worker == current) {
            if (CURRENT.get() != this) {
                CURRENT.set(this);
            }
        } else if (System.nanoTime() - learntAt > RELEARN_NANOS) {
            learn(); // the selector may have moved to another thread
        }
    }

    /** The selector's {@code select()} found {@code count} connections ready: a round begins. */
    void selected(int count) {
        ready = count;
    }

    /**
     * Runs {@code write} at the end of the current thread's round, or at once if it is not in one or its round has
     * no other ready connection.
     */
    static void write(Runnable write) {
        AnswerRound round = CURRENT.get();
        if (round == null || round.worker != Thread.currentThread() || round.ready <= writeAtOnceUpTo) {
            write.run();
            return;
        }
        round.writes.add(write);
        if (round.submitted.compareAndSet(false, true)) {
            round.selector.submit(round); // queued: the selector is working, not selecting, so nothing is woken
        }
    }

    /**
     * True while the current thread writes the answers of its selector's round, at the round's end: a connection
     * answered then should wait for the next {@code select()} to read its client's next request, not read on at
     * once (see {@code FrameConnection}).
     */
    static boolean atRoundEnd() {
        AnswerRound round = CURRENT.get();
        return round != null && round.endingOn == Thread.currentThread();
    }

    private void learn() {
        learntAt = System.nanoTime();
        if (submitted.compareAndSet(false, true)) {
            selector.submit(this);
        }
    }

    /** The end of a round, on the selector's thread. */
    @Override
    public void update(Selector ignored) {
        Thread current = Thread.currentThread();
        if (worker != current) {
            worker = current;
            learntAt = System.nanoTime();
        }
        CURRENT.set(this);
        submitted.set(false);
        endingOn = current;
        try {
            Runnable write;
            while ((write = writes.poll()) != null) {
                try {
                    write.run(); // a write may read on bytes its client sent early, and answer again: run here too
                } catch (RuntimeException e) {
                    System.getLogger(AnswerRound.class.getName()).log(System.Logger.Level.WARNING,
                            "writing an answer failed", e);
                }
            }
        } finally {
            endingOn = null;
        }
    }
}
