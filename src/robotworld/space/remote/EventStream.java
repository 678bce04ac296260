package robotworld.space.remote;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.TimeUnit;

import robotworld.space.ContainerNotFoundException;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.Operation;
import robotworld.space.SpaceException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;
import robotworld.space.wire.Wire;
import robotworld.space.wire.WireReader;

/**
 * The client's notification channel: one streaming HTTP response per session that carries the notifications
 * of all its subscriptions, read by one daemon thread.
 *
 * <p>Frames are numbered; when the stream breaks, the thread reconnects to the same session with the number of
 * the last frame it processed, and the server sends what was lost (also after a graceful server restart, which
 * parks the session with the space). If the server cannot resume the session (it crashed, or the client was
 * away too long), every subscription is established again on a fresh session; a subscription then goes on only
 * if the container's sequence shows that nothing happened while it was away, and otherwise ends as
 * {@link SubscriptionEnd#OVERFLOWED}, so a listener never goes on past a silent gap.
 */
final class EventStream {

    private static final System.Logger LOG = System.getLogger(EventStream.class.getName());

    private final RemoteSpace owner;
    private final Object lock = new Object();
    /** Every subscription not yet ended, established or not. */
    private final Set<RemoteSubscription> subscriptions = new LinkedHashSet<>();
    /** The established ones, by server id on the current session. */
    private final Map<String, RemoteSubscription> byServerId = new HashMap<>();
    /** Frames for server ids whose subscribe answer has not been processed yet. */
    private final Map<String, Parked> early = new HashMap<>();
    private final String sessionId = UUID.randomUUID().toString();
    private Thread reader;
    /** The current incarnation of the session ("id#epoch"), or null while no stream is connected. */
    private String session;
    /** Counts fresh starts of the session: subscriptions of an older epoch are gone on the server. */
    private int epoch;
    /** Number of the last frame processed (reader thread only). */
    private long lastFrame = -1;
    private boolean resubscribeNeeded;
    private volatile HttpConnection connection;
    private volatile boolean closed;

    EventStream(RemoteSpace owner) {
        this.owner = owner;
    }

    /** Establishes a new subscription on the current session (connecting one first if needed). */
    void subscribe(RemoteSubscription subscription, long deadline) {
        while (true) {
            String current = awaitSession(deadline);
            Timeout timeout = subscription.timeoutOnServer();
            Answer answer;
            try {
                answer = owner.subscribeOnServer(sessionId, subscription,
                        timeout == null ? Timeout.TRY_ONCE : timeout);
            } catch (RemoteSpace.SessionGoneException gone) {
                sessionBroke(current);
                continue; // the stream is reconnecting: subscribe on the new one
            }
            subscription.completeUpTo = answer.sequence;
            if (beforeRegistering != null) {
                beforeRegistering.run();
            }
            register(current, answer.subscription, subscription);
            subscription.established(owner.timer());
            return;
        }
    }

    /** Forgets an ended subscription. */
    void forget(RemoteSubscription subscription) {
        synchronized (lock) {
            subscriptions.remove(subscription);
            if (subscription.serverId != null) {
                byServerId.remove(subscription.serverId, subscription);
            }
        }
    }

    /**
     * Makes {@code subscription} the receiver of {@code serverId}'s frames. Frames that came before it was
     * registered are delivered first, and frames still coming meanwhile wait behind them, so the listener sees the
     * container's order: the subscription becomes reachable by the reader only once nothing of it is parked.
     */
    private void register(String usedSession, String serverId, RemoteSubscription subscription) {
        synchronized (lock) {
            subscriptions.add(subscription);
            if (!usedSession.equals(session)) {
                resubscribeNeeded = true; // the session broke meanwhile: the reader re-establishes it
                return;
            }
            // established on this session (so the reader does not subscribe it again, and a cancel reaches the
            // server), though not yet reachable for the reader's frames
            subscription.session = usedSession;
            subscription.serverId = serverId;
        }
        while (true) {
            Parked parked;
            synchronized (lock) {
                if (!usedSession.equals(session)) {
                    subscription.session = null;
                    subscription.serverId = null;
                    resubscribeNeeded = true;
                    return;
                }
                parked = early.remove(serverId);
                if (!subscription.isActive()) {
                    break; // ended while its parked frames were handed over (its queue overflowed)
                }
                if (parked == null) {
                    byServerId.put(serverId, subscription);
                    return;
                }
            }
            if (beforeParkedFramesDelivered != null) {
                beforeParkedFramesDelivered.run();
            }
            for (Frame frame : parked.frames) {
                deliver(subscription, frame);
                if (frame.end != null) {
                    return; // ended on the server before the client knew it: nothing more will come
                }
            }
            if (parked.overflowed) {
                subscription.overflowed(); // frames were dropped while it waited: say so rather than go on
                break;
            }
        }
        forget(subscription); // ended here: its server side was asked to stop, and its end frame finds no one
    }

    /** Test hook: runs when a new subscription's answer is in and it is about to be registered. */
    volatile Runnable beforeRegistering;
    /** Test hook: runs when frames parked for a subscription are about to be delivered to it. */
    volatile Runnable beforeParkedFramesDelivered;

    /** The number of the last frame the reader processed (for tests). */
    long lastFrameRead() {
        synchronized (lock) {
            return lastFrame;
        }
    }

    private String awaitSession(long deadline) {
        synchronized (lock) {
            if (reader == null) {
                reader = new Thread(this::run, "space-client-events");
                reader.setDaemon(true);
                reader.start();
            }
            while (session == null) {
                if (closed || owner.isClosed()) {
                    throw new robotworld.space.SpaceClosedException("the remote space is closed");
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new SpaceUnavailableException(owner.url(), "no notification stream to the space server",
                            null);
                }
                try {
                    lock.wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new robotworld.space.SpaceInterruptedException("interrupted while subscribing", e);
                }
            }
            return session;
        }
    }

    private void sessionBroke(String broken) {
        synchronized (lock) {
            if (broken.equals(session)) {
                session = null;
                lastFrame = -1; // the server does not know the session: start afresh
            }
        }
        HttpConnection current = connection;
        if (current != null) {
            current.close();
        }
    }

    // ---- the reader thread ----

    private void run() {
        int attempt = 0;
        while (!closed) {
            HttpConnection stream = null;
            Endpoint used = owner.endpoint();
            try {
                long after;
                synchronized (lock) {
                    after = lastFrame;
                }
                stream = open(after);
                connection = stream;
                synchronized (lock) {
                    if (!resumed) {
                        epoch++;
                        lastFrame = 0;
                        detachAll();
                    }
                    session = sessionId + "#" + epoch;
                    lock.notifyAll();
                }
                attempt = 0;
                long idle = TimeUnit.MILLISECONDS.toNanos(3 * heartbeatMillis + owner.options.networkAllowanceMillis());
                while (!closed) {
                    if (takeResubscribeFlag()) {
                        resubscribeAll();
                    }
                    byte[] line = stream.readLine(System.nanoTime() + idle, () -> { });
                    if (line == null) {
                        break;
                    }
                    if (line.length > 0) {
                        dispatch(line);
                    }
                }
            } catch (IOException | SpaceException e) {
                if (!closed) {
                    LOG.log(System.Logger.Level.DEBUG, "notification stream broke: " + e);
                    if (e instanceof IOException && stream == null) {
                        owner.failover(used, e); // its server does not answer: with several, try the next one
                    }
                }
            } finally {
                if (stream != null) {
                    stream.close();
                }
                synchronized (lock) {
                    session = null;
                }
            }
            if (!closed) {
                owner.pool.discardIdle();
                sleep(Math.min(250, 5L << Math.min(attempt++, 6)));
            }
        }
    }

    private long heartbeatMillis = 2_000;
    /** Whether the last {@link #open} resumed the session (reader thread only). */
    private boolean resumed;

    private HttpConnection open(long after) throws IOException {
        Endpoint endpoint = owner.endpoint(); // the next server if the last one failed
        HttpConnection stream = new HttpConnection(endpoint.host(), endpoint.port(),
                owner.options.connectTimeoutMillis());
        try {
            stream.send("GET", endpoint.path("events") + "?session=" + sessionId + "&after=" + after,
                    endpoint.authorization(), null, 0);
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(owner.options.networkAllowanceMillis());
            int status = stream.receiveStreamHead(deadline, () -> { });
            if (status != 200) {
                throw new IOException("the server refused the notification stream with HTTP " + status);
            }
            byte[] hello = stream.readLine(deadline, () -> { });
            if (hello == null) {
                throw new IOException("the notification stream ended at once");
            }
            resumed = false;
            try (WireReader in = owner.wire.reader(hello, 0, hello.length)) {
                in.startObject();
                String field;
                while ((field = in.nextField()) != null) {
                    switch (field) {
                        case "heartbeat" -> heartbeatMillis = Math.max(10, in.readLong("heartbeat"));
                        case "resumed" -> resumed = in.readBoolean("resumed");
                        default -> in.skipValue();
                    }
                }
            }
            return stream;
        } catch (IOException | RuntimeException e) {
            stream.close();
            throw e;
        }
    }

    private boolean takeResubscribeFlag() {
        synchronized (lock) {
            boolean needed = resubscribeNeeded;
            resubscribeNeeded = false;
            return needed;
        }
    }

    /** Re-establishes every subscription that is not established on the current session. */
    private void resubscribeAll() {
        List<RemoteSubscription> detached = new ArrayList<>();
        String current;
        synchronized (lock) {
            current = session;
            for (RemoteSubscription subscription : subscriptions) {
                if (current == null || !current.equals(subscription.session)) {
                    detached.add(subscription);
                }
            }
        }
        if (current == null) {
            return;
        }
        for (RemoteSubscription subscription : detached) {
            if (subscription.cancelRequested()) {
                end(subscription, SubscriptionEnd.CANCELLED);
                continue;
            }
            Timeout timeout = subscription.timeoutOnServer();
            if (timeout == null) {
                end(subscription, SubscriptionEnd.EXPIRED);
                continue;
            }
            Answer answer;
            try {
                answer = owner.subscribeOnServer(sessionId, subscription, timeout);
            } catch (ContainerNotFoundException gone) {
                end(subscription, SubscriptionEnd.CONTAINER_DESTROYED);
                continue;
            }
            if (answer.sequence != subscription.completeUpTo) {
                // operations happened while it was away, and it cannot know whether it wanted them
                owner.call("unsubscribe", null, RemoteSpace.Retry.IDEMPOTENT, (out, callId, wait) ->
                        out.field("session", sessionId).field("subscription", answer.subscription));
                end(subscription, SubscriptionEnd.OVERFLOWED);
                continue;
            }
            register(current, answer.subscription, subscription);
            subscription.established(owner.timer());
        }
    }

    private void end(RemoteSubscription subscription, SubscriptionEnd reason) {
        subscription.end(reason);
        forget(subscription);
    }

    /** The server started the session afresh: every subscription must be established again. Under the lock. */
    private void detachAll() {
        byServerId.clear();
        early.clear();
        for (RemoteSubscription subscription : subscriptions) {
            subscription.session = null;
            subscription.serverId = null;
        }
        resubscribeNeeded = true;
    }

    // ---- frames ----

    /** One frame of the stream: a notification ({@code operation} set), an end, or a heartbeat (no {@code sub}). */
    private record Frame(String sub, long number, Operation operation, long sequence, List<Entry> entries,
                         List<Entry> displaced, String end) { }

    private Frame parse(byte[] line) {
        String sub = null;
        Operation operation = null;
        long sequence = -1;
        List<Entry> entries = List.of();
        List<Entry> displaced = List.of();
        String end = null;
        long number = -1;
        try (WireReader in = owner.wire.reader(line, 0, line.length)) {
            in.startObject();
            String field;
            while ((field = in.nextField()) != null) {
                switch (field) {
                    case "sub" -> sub = in.readString("sub");
                    case "op" -> operation = in.readOperation();
                    case "seq" -> sequence = in.readLong("seq");
                    case "entries" -> entries = in.readEntries("entries");
                    case "displaced" -> displaced = in.readEntries("displaced");
                    case "end" -> end = in.readString("end");
                    case "n" -> number = in.readLong("n");
                    default -> in.skipValue();
                }
            }
        }
        return new Frame(sub, number, operation, sequence, entries, displaced, end);
    }

    /** A frame read from the stream (reader thread only). */
    private void dispatch(byte[] line) {
        Frame frame = parse(line);
        if (frame.sub == null) {
            return; // heartbeat
        }
        RemoteSubscription subscription;
        synchronized (lock) {
            if (frame.number >= 0) {
                if (frame.number <= lastFrame) {
                    return; // sent again after a reconnect, but processed already
                }
                lastFrame = frame.number;
            }
            subscription = byServerId.get(frame.sub);
            if (subscription == null) {
                park(frame); // its subscribe answer is still on the way (or it ended a moment ago)
                return;
            }
            if (frame.end != null) {
                byServerId.remove(frame.sub);
            }
        }
        deliver(subscription, frame);
    }

    /**
     * Frames that came before their subscription's subscribe answer. Frames of a subscription that ended on the
     * client while the server still sent are parked too and never claimed: they are dropped after a while.
     */
    private static final class Parked {
        final long since = System.nanoTime();
        final List<Frame> frames = new ArrayList<>();
        boolean overflowed;
    }

    private static final int MAX_PARKED_FRAMES = 10_000;

    /** Under the lock. */
    private void park(Frame frame) {
        long now = System.nanoTime();
        long unclaimed = TimeUnit.MILLISECONDS.toNanos(60_000 + 2L * owner.options.networkAllowanceMillis());
        early.values().removeIf(parked -> now - parked.since > unclaimed);
        Parked parked = early.computeIfAbsent(frame.sub, key -> new Parked());
        if (parked.frames.size() < MAX_PARKED_FRAMES) {
            parked.frames.add(frame);
        } else {
            parked.overflowed = true;
        }
    }

    private void deliver(RemoteSubscription subscription, Frame frame) {
        if (frame.operation != null) {
            subscription.offer(new Notification(subscription.container, frame.operation, frame.entries,
                    frame.displaced, frame.sequence));
        } else if (frame.end != null) {
            end(subscription, Wire.subscriptionEnd(frame.end));
        }
    }

    // ---- shutdown ----

    /** Whether a session was ever opened (then close() ends it on the server). */
    boolean started() {
        synchronized (lock) {
            return reader != null;
        }
    }

    String sessionId() {
        return sessionId;
    }

    void close() {
        List<RemoteSubscription> all;
        synchronized (lock) {
            closed = true;
            all = new ArrayList<>(subscriptions);
            subscriptions.clear();
            byServerId.clear();
            lock.notifyAll();
        }
        HttpConnection current = connection;
        if (current != null) {
            current.close();
        }
        for (RemoteSubscription subscription : all) {
            subscription.end(SubscriptionEnd.SPACE_CLOSED);
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
