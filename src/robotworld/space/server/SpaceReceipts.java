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

import robotworld.space.SpaceEngine;
import robotworld.space.Entry;

/**
 * What a space's servers promised their clients, kept with the space rather than with one server: the takes
 * waiting for their client's confirmation ({@link LeaseTable}) and the recent writes that happened. A server
 * restarted in front of the same space therefore still accepts the confirmations of answers its predecessor
 * sent, and can still tell a client whose answer was lost whether its write happened. Unconfirmed takes are
 * put back when their lease runs out, whether or not a server is running. Completed writes and shifts are
 * remembered (the last 10 000) so that a client whose answer was lost can ask instead of repeating them.
 */
final class SpaceReceipts {

    private static final int MAX_COMPLETED = 10_000;
    private static final Map<SpaceEngine, SpaceReceipts> BY_SPACE = new WeakHashMap<>();
    private static final ScheduledExecutorService TIMER = Executors.newSingleThreadScheduledExecutor(task -> {
        Thread thread = new Thread(task, "space-server-leases");
        thread.setDaemon(true);
        return thread;
    });

    final LeaseTable leases = new LeaseTable();
    /** Recent writes and shifts that happened, with what each shift displaced. */
    private final Map<String, List<Entry>> completed = new LinkedHashMap<>();

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

    /** Remembers that the write of {@code callId} happened. */
    void writeCompleted(String callId) {
        completed(callId, List.of());
    }

    /** Remembers that the shift of {@code callId} happened and what it displaced. */
    void completed(String callId, List<Entry> displaced) {
        synchronized (completed) {
            if (completed.size() >= MAX_COMPLETED) {
                completed.remove(completed.keySet().iterator().next());
            }
            completed.put(callId, displaced);
        }
    }

    /** What the write or shift of {@code callId} displaced if it happened (recently), else null; forgets it. */
    List<Entry> takeCompleted(String callId) {
        synchronized (completed) {
            return completed.remove(callId);
        }
    }
}
