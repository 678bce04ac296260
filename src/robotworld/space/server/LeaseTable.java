package robotworld.space.server;

import java.util.Iterator;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import robotworld.space.Removal;

/**
 * Takes and destroys whose client has not yet confirmed that it received the answer. A confirmation (ack) drops
 * the removal for good; a missing one restores the entries after the lease time, and a cancel restores them at
 * once. So an entry whose answer never reached its client is never lost.
 */
final class LeaseTable {

    private final Map<String, Lease> leases = new ConcurrentHashMap<>();

    /** Holds a removal until {@code callId} is acknowledged, or {@code leaseMillis} have passed. */
    void hold(String callId, Removal removal, long leaseMillis) {
        Lease previous = leases.put(callId, new Lease(removal,
                System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(leaseMillis)));
        if (previous != null) {
            previous.removal.restore(); // a client reusing a call id: keep nothing hostage
        }
    }

    /** The client received the answer: the removal stands. */
    void acknowledge(String callId) {
        leases.remove(callId);
    }

    /** Undoes the removal of {@code callId}; whether there was one. */
    boolean restore(String callId) {
        Lease lease = leases.remove(callId);
        if (lease == null) {
            return false;
        }
        lease.removal.restore();
        return true;
    }

    /** Restores the removals whose lease ran out. */
    void expire() {
        long now = System.nanoTime();
        for (Iterator<Map.Entry<String, Lease>> it = leases.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<String, Lease> entry = it.next();
            if (now - entry.getValue().expiresAt >= 0 && leases.remove(entry.getKey(), entry.getValue())) {
                entry.getValue().removal.restore();
            }
        }
    }

    /** Restores every removal still unconfirmed. */
    void restoreAll() {
        for (String callId : leases.keySet()) {
            restore(callId);
        }
    }

    int size() {
        return leases.size();
    }

    private record Lease(Removal removal, long expiresAt) {
    }
}
