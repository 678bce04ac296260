package robotworld.space.server;

import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * One client's notification channel: the subscriptions it made and the frames waiting to be streamed to it.
 *
 * <p>Frames are numbered. The session outlives a broken stream for a grace period (and a graceful server
 * restart, see {@link ParkedSessions}): its subscriptions keep queueing frames, and the client reconnects with
 * the number of the last frame it processed. The last {@link #RING} frames sent are kept, so frames lost in a
 * broken connection are sent again; a client that is further behind cannot resume and starts over.
 *
 * <p>Notification frames are bounded per session (a client that does not read loses its subscriptions with an
 * overflow, never the server its memory); end frames always fit, one per subscription.
 */
final class EventSession {

    /** How many sent frames are kept for a resuming client, and how many bytes of them at most. */
    static final int RING = 1024;
    static final long RING_BYTES = 4L << 20;
    /** Bytes of notification frames one session may queue (besides the frame count). */
    static final long QUEUE_BYTES = 32L << 20;

    /** One numbered line of the stream; notification frames count against the session's capacity. */
    record Frame(long number, byte[] bytes, boolean notification) {
    }

    /** What a stream gets from {@link #next}: a frame, or nothing yet (heartbeat), or the end of this stream. */
    static final Frame END = new Frame(-1, new byte[0], false);

    final String id;
    private final int capacity;
    private final ArrayDeque<Frame> queue = new ArrayDeque<>();
    private final ArrayDeque<Frame> sent = new ArrayDeque<>();
    private int queuedNotifications;
    private long queuedBytes;
    private long ringBytes;
    private long lastNumber;
    /** Which stream may take frames; a new stream (or a stop) makes the current one end. */
    private long generation;
    private boolean streamAttached;
    private boolean closing;
    private long detachedSince = System.nanoTime();
    private final Map<String, Forwarder> forwarders = new ConcurrentHashMap<>();
    private final AtomicLong lastSubscriptionId = new AtomicLong();

    EventSession(String id, int capacity) {
        this.id = id;
        this.capacity = capacity;
    }

    // ---- subscriptions ----

    String nextSubscriptionId() {
        return Long.toString(lastSubscriptionId.incrementAndGet());
    }

    void add(Forwarder forwarder) {
        forwarders.put(forwarder.id, forwarder);
    }

    Forwarder forwarder(String subscriptionId) {
        return forwarders.get(subscriptionId);
    }

    Collection<Forwarder> forwarders() {
        return forwarders.values();
    }

    /** Queues a notification frame (its JSON object without the opening brace); false if the queue is full. */
    synchronized boolean offerNotification(byte[] objectTail) {
        if (closing || queuedNotifications >= capacity || queuedBytes + objectTail.length > QUEUE_BYTES) {
            return false;
        }
        queuedNotifications++;
        queuedBytes += enqueue(objectTail, true);
        return true;
    }

    /** Queues the last frame of a subscription (null for none) and forgets the subscription. */
    void ended(Forwarder forwarder, byte[] objectTail) {
        synchronized (this) {
            if (objectTail != null && !closing) {
                enqueue(objectTail, false);
            }
        }
        forwarders.remove(forwarder.id, forwarder);
    }

    /** Numbers and queues a frame; returns its size. */
    private int enqueue(byte[] objectTail, boolean notification) {
        long number = ++lastNumber;
        byte[] prefix = ("{\"n\":" + number + ",").getBytes(StandardCharsets.US_ASCII);
        byte[] line = new byte[prefix.length + objectTail.length];
        System.arraycopy(prefix, 0, line, 0, prefix.length);
        System.arraycopy(objectTail, 0, line, prefix.length, objectTail.length);
        queue.add(new Frame(number, line, notification));
        notifyAll();
        return line.length;
    }

    // ---- streams ----

    /**
     * Attaches a new stream that has processed every frame up to {@code after}; the previous stream, if any,
     * ends.
     *
     * @return the stream's generation and the frames to send again, or null if the client is too far behind
     */
    synchronized Attachment attach(long after) {
        if (after > lastNumber || (after < lastNumber && !canReplayFrom(after))) {
            return null;
        }
        List<Frame> replay = new ArrayList<>();
        for (Frame frame : sent) {
            if (frame.number() > after) {
                replay.add(frame);
            }
        }
        generation++;
        streamAttached = true;
        notifyAll(); // the previous stream's writer sees the new generation and ends
        return new Attachment(generation, replay);
    }

    private boolean canReplayFrom(long after) {
        long oldestNeeded = after + 1;
        Frame oldestQueued = queue.peekFirst();
        if (oldestQueued != null && oldestQueued.number() <= oldestNeeded) {
            return true;
        }
        Frame oldestSent = sent.peekFirst();
        return oldestSent != null && oldestSent.number() <= oldestNeeded;
    }

    /** A stream's claim on the session. */
    record Attachment(long generation, List<Frame> replay) {
    }

    /**
     * The next frame for the stream of {@code generation}: waits at most {@code timeoutNanos} and returns null if
     * nothing came, or {@link #END} when this stream must end (superseded, stopping, or the session is closed).
     */
    synchronized Frame next(long generation, long timeoutNanos) throws InterruptedException {
        long deadline = System.nanoTime() + timeoutNanos;
        while (true) {
            if (generation != this.generation) {
                return END;
            }
            Frame frame = queue.pollFirst();
            if (frame != null) {
                if (frame.notification()) {
                    queuedNotifications--;
                    queuedBytes -= frame.bytes().length;
                }
                sent.addLast(frame);
                ringBytes += frame.bytes().length;
                while (sent.size() > RING || (ringBytes > RING_BYTES && sent.size() > 1)) {
                    ringBytes -= sent.removeFirst().bytes().length;
                }
                return frame;
            }
            if (closing) {
                return END;
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return null;
            }
            TimeUnit.NANOSECONDS.timedWait(this, left);
        }
    }

    /** The stream of {@code generation} ended; the session waits for a resuming client. */
    synchronized void detached(long generation) {
        if (generation == this.generation) {
            streamAttached = false;
            detachedSince = System.nanoTime();
        }
    }

    /** Ends the current stream after it has sent what is queued (a graceful stop); the session lives on. */
    synchronized void endStream() {
        generation++;
        notifyAll();
    }

    /** Whether no stream has been attached for longer than {@code graceNanos}. */
    synchronized boolean abandonedFor(long graceNanos) {
        return !streamAttached && System.nanoTime() - detachedSince > graceNanos;
    }

    synchronized boolean hasStream() {
        return streamAttached;
    }

    /** Ends the session: the stream ends, nothing more is queued; the caller cancels the subscriptions. */
    synchronized void close() {
        closing = true;
        queue.clear();
        sent.clear();
        queuedNotifications = 0;
        queuedBytes = 0;
        ringBytes = 0;
        generation++;
        notifyAll();
    }

    synchronized boolean isClosing() {
        return closing;
    }
}
