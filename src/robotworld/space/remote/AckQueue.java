package robotworld.space.remote;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Predicate;

/**
 * Confirmations of takes that still have to reach the server. They ride in a header on the next request of any
 * thread, which costs no extra round trip; if no request goes out soon, a background flush sends them alone.
 */
final class AckQueue {

    /** Keeps the header far below the server's 16 KiB header limit (a call id with its container is about 45 characters). */
    private static final int MAX_PER_REQUEST = 128;

    private final ConcurrentLinkedQueue<String> pending = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean flushScheduled = new AtomicBoolean();
    private final ScheduledExecutorService timer;
    private final long delayMicros;
    private final Predicate<String> flusher;

    /**
     * @param timer   runs the background flush
     * @param delayMicros how long an ack may wait for a request to ride on
     * @param flusher sends a header value on its own; false if that failed (the acks are then re-queued)
     */
    AckQueue(ScheduledExecutorService timer, long delayMicros, Predicate<String> flusher) {
        this.timer = timer;
        this.delayMicros = delayMicros;
        this.flusher = flusher;
    }

    void add(String callId) {
        pending.add(callId);
        scheduleFlush(delayMicros);
    }

    /** Takes up to a request's worth of acks as a header value, or null if none are pending. */
    String drain() {
        String first = pending.poll();
        if (first == null) {
            return null;
        }
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

    boolean isEmpty() {
        return pending.isEmpty();
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
