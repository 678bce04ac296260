package robotworld.space.server;

import java.lang.ref.WeakReference;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

import robotworld.space.CallReceipts;
import robotworld.space.Entry;
import robotworld.space.Removal;
import robotworld.space.SpaceEngine;

/**
 * What a space's servers promised their clients, kept with the space rather than with one server: the takes
 * waiting for their client's confirmation ({@link LeaseTable}) and the recent writes that happened. A server
 * restarted in front of the same space therefore still accepts the confirmations of answers its predecessor
 * sent, and can still tell a client whose answer was lost whether its write happened. Unconfirmed takes are
 * put back when their lease runs out, whether or not a server is running. Completed writes and shifts are
 * remembered (the last 10 000) so that a client whose answer was lost can ask instead of repeating them, and so
 * are calls cancelled before they arrived, so that they are refused when they do.
 *
 * <p>This is where a server keeps them for a space that does not keep them itself ({@link SpaceEngine#receipts()}).
 */
final class SpaceReceipts implements CallReceipts {

    private static final int MAX_COMPLETED = 10_000;
    /** How long an early cancel is remembered, and how many at most. */
    private static final long TOMBSTONE_NANOS = TimeUnit.SECONDS.toNanos(60);
    private static final int MAX_TOMBSTONES = 10_000;
    private static final Map<SpaceEngine, SpaceReceipts> BY_SPACE = new WeakHashMap<>();
    private static final ScheduledExecutorService TIMER = Executors.newSingleThreadScheduledExecutor(task -> {
        Thread thread = new Thread(task, "space-server-leases");
        thread.setDaemon(true);
        return thread;
    });

    final LeaseTable leases = new LeaseTable();
    /** Recent writes and shifts that happened, with what each shift displaced. */
    private final Map<String, List<Entry>> completed = new LinkedHashMap<>();
    /** Calls cancelled before they arrived, with when. */
    private final Map<String, Long> tombstones = new LinkedHashMap<>();

    private SpaceReceipts() {
    }

    /** The receipts of {@code space}, created on first use; expired leases are checked every few milliseconds. */
    static SpaceReceipts of(SpaceEngine space) {
        synchronized (BY_SPACE) {
            SpaceReceipts receipts = BY_SPACE.get(space);
            if (receipts == null) {
                receipts = new SpaceReceipts();
                BY_SPACE.put(space, receipts);
                scheduleExpiry(receipts);
            }
            return receipts;
        }
    }

    private static void scheduleExpiry(SpaceReceipts receipts) {
        WeakReference<SpaceReceipts> weak = new WeakReference<>(receipts);
        ScheduledFuture<?>[] task = new ScheduledFuture<?>[1];
        synchronized (task) {
            task[0] = TIMER.scheduleWithFixedDelay(() -> {
                SpaceReceipts alive = weak.get();
                if (alive == null) {
                    synchronized (task) {
                        task[0].cancel(false); // the space is gone
                    }
                    return;
                }
                alive.leases.expire();
            }, 10, 10, TimeUnit.MILLISECONDS);
        }
    }

    @Override
    public void hold(String callId, Removal removal, long leaseMillis) {
        leases.hold(callId, removal, leaseMillis);
    }

    @Override
    public void acknowledge(String callId) {
        leases.acknowledge(callId);
    }

    @Override
    public boolean restore(String callId) {
        return leases.restore(callId);
    }

    @Override
    public int held() {
        return leases.size();
    }

    /** Remembers that the write or shift of {@code callId} happened and what it displaced. */
    @Override
    public void completed(String callId, List<Entry> displaced) {
        synchronized (completed) {
            if (completed.size() >= MAX_COMPLETED) {
                completed.remove(completed.keySet().iterator().next());
            }
            completed.put(callId, displaced);
        }
    }

    /** What the write or shift of {@code callId} displaced if it happened (recently), else null; forgets it. */
    @Override
    public List<Entry> takeCompleted(String callId) {
        synchronized (completed) {
            return completed.remove(callId);
        }
    }

    /** Remembers the cancel for a while, so that the call is refused if it still arrives; null (it did not run). */
    @Override
    public List<Entry> forbid(String callId) {
        long now = System.nanoTime();
        synchronized (tombstones) {
            tombstones.values().removeIf(at -> now - at > TOMBSTONE_NANOS);
            if (tombstones.size() >= MAX_TOMBSTONES) {
                tombstones.remove(tombstones.keySet().iterator().next());
            }
            tombstones.put(callId, now);
        }
        return null;
    }

    @Override
    public boolean isForbidden(String callId) {
        synchronized (tombstones) {
            return !tombstones.isEmpty() && tombstones.remove(callId) != null;
        }
    }
}
