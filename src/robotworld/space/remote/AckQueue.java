package robotworld.space.remote;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Predicate;

/**
 * Confirmations of takes that still have to reach the server. They ride in a header on the next request of any
 * thread, which costs no extra round trip; if no request takes them within the delay, the JVM's {@link AckSweeper}
 * notices and this space's timer sends them alone (a delay of 0: at once). A confirmation so waits between the
 * delay and the delay plus two of the sweeper's ticks when no request comes.
 */
final class AckQueue {

    /** Keeps the header far below the server's 16 KiB header limit (a call id with its container is about 45 characters). */
    private static final int MAX_PER_REQUEST = 128;

    private final ConcurrentLinkedQueue<String> pending = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean flushScheduled = new AtomicBoolean();
    private final ScheduledExecutorService timer;
    private final long delayMicros;
    private final long delayNanos;
    private final Predicate<String> flusher;
    private final AckSweeper sweeper;
    /** How many times requests took confirmations: the sweeper's sign that they are moving. */
    private volatile long drains;
    /** The sweeper's own: whether it saw confirmations waiting, since when, and after how many drains. */
    private boolean seen;
    private long seenSince;
    private long seenDrains;

    /**
     * @param timer   runs the background flush
     * @param delayMicros how long an ack may wait for a request to ride on
     * @param flusher sends a header value on its own; false if that failed (the acks are then re-queued)
     */
    AckQueue(ScheduledExecutorService timer, long delayMicros, Predicate<String> flusher) {
        this(timer, delayMicros, flusher, AckSweeper.shared());
    }

    AckQueue(ScheduledExecutorService timer, long delayMicros, Predicate<String> flusher, AckSweeper sweeper) {
        this.sweeper = sweeper;
        this.timer = timer;
        this.delayMicros = delayMicros;
        this.delayNanos = TimeUnit.MICROSECONDS.toNanos(delayMicros);
        this.flusher = flusher;
        if (delayMicros > 0) {
            sweeper.register(this);
        }
    }

    void add(String callId) {
        pending.add(callId);
        if (delayMicros == 0) {
            scheduleFlush(0);
        } else {
            sweeper.pending();
        }
    }

    /** Stops the sweeps of this queue (the space is closing; it sends what is left itself). */
    void close() {
        sweeper.unregister(this);
    }

    /**
     * Called by the sweeper every tick: has this space's timer send the confirmations that have waited at least the
     * delay without a request taking any. True if confirmations are outstanding.
     */
    boolean sweep(long now) {
        if (pending.isEmpty()) {
            seen = false;
            return false;
        }
        long drainsNow = drains;
        if (!seen || drainsNow != seenDrains) {
            seen = true; // newly waiting, or requests took some since the last look: count from now
            seenSince = now;
            seenDrains = drainsNow;
        } else if (now - seenSince >= delayNanos) {
            seen = false;
            scheduleFlush(0);
        }
        return true;
    }

    /** Takes up to a request's worth of acks as a header value, or null if none are pending. */
    String drain() {
        String first = pending.poll();
        if (first == null) {
            return null;
        }
        drains++; // racy increments may be lost; the sweeper only needs to see a change
        StringBuilder header = new StringBuilder(first);
        String next;
        for (int i = 1; i < MAX_PER_REQUEST && (next = pending.poll()) != null; i++) {
            header.append(',').append(next);
        }
        return header.toString();
    }

    /** Puts back acks whose request failed. */
    void requeue(String header) {
        if (header != null) {
            for (String id : header.split(",")) {
                pending.add(id);
            }
            scheduleFlush(TimeUnit.MILLISECONDS.toMicros(20));
        }
    }

    private void scheduleFlush(long micros) {
        if (flushScheduled.compareAndSet(false, true)) {
            try {
                timer.schedule(this::flush, micros, TimeUnit.MICROSECONDS);
            } catch (java.util.concurrent.RejectedExecutionException closed) {
                flushScheduled.set(false);
            }
        }
    }

    private void flush() {
        flushScheduled.set(false);
        String header;
        while ((header = drain()) != null) {
            if (!flusher.test(header)) {
                requeue(header); // retried a little later
                return;
            }
        }
    }
}
