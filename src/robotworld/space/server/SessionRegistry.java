package robotworld.space.server;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The notification sessions of a server, streaming or waiting for their client to reconnect; at most a fixed
 * number at once.
 */
final class SessionRegistry {

    private final Map<String, EventSession> sessions = new ConcurrentHashMap<>();
    private final int maxSessions;
    private final int queueCapacity;

    SessionRegistry(int maxSessions, int queueCapacity) {
        this.maxSessions = maxSessions;
        this.queueCapacity = queueCapacity;
    }

    /** A stream opened on a session: whether it resumed an existing one, and its attachment. */
    record Opened(EventSession session, EventSession.Attachment attachment, boolean resumed) {
    }

    /**
     * Attaches a stream to session {@code id}: resumes it if it exists and the client has processed frames up to
     * {@code after} that can still be sent again; otherwise starts the session afresh.
     *
     * @throws IllegalStateException if the maximum number of sessions exists
     */
    synchronized Opened open(String id, long after) {
        EventSession existing = sessions.get(id);
        if (existing != null && !existing.isClosing()) {
            if (after >= 0) {
                EventSession.Attachment attachment = existing.attach(after);
                if (attachment != null) {
                    return new Opened(existing, attachment, true);
                }
            }
            close(existing); // cannot resume: start over under the same id
        }
        if (sessions.size() >= maxSessions) {
            throw new IllegalStateException("too many notification sessions (" + maxSessions + ")");
        }
        EventSession session = new EventSession(id, queueCapacity);
        sessions.put(id, session);
        return new Opened(session, session.attach(0), false);
    }

    EventSession get(String id) {
        return sessions.get(id);
    }

    /** Ends a session and cancels its subscriptions. */
    void close(EventSession session) {
        sessions.remove(session.id, session);
        closeQuietly(session);
    }

    static void closeQuietly(EventSession session) {
        session.close();
        for (Forwarder forwarder : session.forwarders()) {
            forwarder.cancel();
        }
    }

    /** Ends the sessions whose client has not reconnected within {@code graceNanos}. */
    void expire(long graceNanos) {
        for (EventSession session : sessions.values()) {
            if (session.abandonedFor(graceNanos)) {
                close(session);
            }
        }
    }

    Collection<EventSession> all() {
        return sessions.values();
    }

    /** Takes over sessions a stopped server left behind. */
    synchronized void adopt(Collection<EventSession> parked) {
        for (EventSession session : parked) {
            sessions.putIfAbsent(session.id, session);
        }
    }

    /** Hands every session over (for parking), leaving this registry empty. */
    synchronized List<EventSession> releaseAll() {
        List<EventSession> all = new ArrayList<>(sessions.values());
        sessions.clear();
        return all;
    }
}
