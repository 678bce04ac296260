package robotworld.space.server;

import java.util.ArrayList;
import java.util.Collection;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

import robotworld.space.SpaceEngine;

/**
 * Notification sessions of a gracefully stopped server, kept with their space for a grace period: their
 * subscriptions keep running and queueing frames, and a server started in front of the same space adopts them,
 * so its clients resume their streams without a gap. Sessions nobody adopts in time are closed.
 */
final class ParkedSessions {

    private static final Map<SpaceEngine, List<EventSession>> PARKED = new IdentityHashMap<>();
    private static final ScheduledExecutorService TIMER = Executors.newSingleThreadScheduledExecutor(task -> {
        Thread thread = new Thread(task, "space-server-parked-sessions");
        thread.setDaemon(true);
        return thread;
    });

    private ParkedSessions() {
    }

    static void park(SpaceEngine space, Collection<EventSession> sessions, long graceMillis) {
        if (sessions.isEmpty()) {
            return;
        }
        List<EventSession> batch = new ArrayList<>(sessions);
        synchronized (PARKED) {
            PARKED.computeIfAbsent(space, key -> new ArrayList<>()).addAll(batch);
        }
        TIMER.schedule(() -> expire(space, batch), graceMillis, TimeUnit.MILLISECONDS);
    }

    /** The sessions parked for {@code space}, now owned by the caller. */
    static List<EventSession> adopt(SpaceEngine space) {
        synchronized (PARKED) {
            List<EventSession> sessions = PARKED.remove(space);
            return sessions == null ? List.of() : sessions;
        }
    }

    private static void expire(SpaceEngine space, List<EventSession> batch) {
        List<EventSession> expired = new ArrayList<>();
        synchronized (PARKED) {
            List<EventSession> parked = PARKED.get(space);
            if (parked == null) {
                return;
            }
            for (EventSession session : batch) {
                if (parked.remove(session)) {
                    expired.add(session);
                }
            }
            if (parked.isEmpty()) {
                PARKED.remove(space);
            }
        }
        expired.forEach(SessionRegistry::closeQuietly);
    }
}
