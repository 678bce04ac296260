package robotworld.cluster;

import java.util.concurrent.atomic.AtomicBoolean;

import robotworld.space.ContainerRef;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.internal.QueuedSubscription;

/**
 * A subscription made on this member: registered with its container (which then passes its events to this
 * member), fed in order by the container's {@link EventInbox}, and delivered like an embedded subscription (modes,
 * timeouts, bounded queue, one delivery task at a time) by a {@link QueuedSubscription}.
 */
final class ClusterSubscription implements Subscription {

    private final ClusterSpace space;
    private final String container;
    private final OpId id;
    private final EventInbox inbox;
    private QueuedSubscription queued;
    /** The container's sequence when it was registered: it sees only later events. */
    private long from;
    private final AtomicBoolean unregistered = new AtomicBoolean();

    ClusterSubscription(ClusterSpace space, String container, OpId id, EventInbox inbox) {
        this.space = space;
        this.container = container;
        this.id = id;
        this.inbox = inbox;
    }

    void start(QueuedSubscription subscription, long sequence) {
        this.queued = subscription;
        this.from = sequence;
    }

    OpId id() {
        return id;
    }

    QueuedSubscription queued() {
        return queued;
    }

    long from() {
        return from;
    }

    @Override
    public ContainerRef container() {
        return queued.container();
    }

    @Override
    public boolean isActive() {
        return queued.isActive();
    }

    /**
     * Unregisters at the container first (so that it is no longer counted when {@code cancel} returns), then ends:
     * what happened before is still delivered, then {@link SubscriptionEnd#CANCELLED}.
     */
    @Override
    public void cancel() {
        if (!queued.isActive()) {
            return;
        }
        // events of calls made through other members may still be on their way here: what happened before the
        // cancel is delivered first (read from the container's journal if need be)
        long before = space.chainTailOf(container);
        if (before >= 0) {
            inbox.awaitDelivered(before, System.nanoTime() + CATCH_UP_NANOS);
        }
        if (unregistered.compareAndSet(false, true)) {
            space.unregister(container, id);
        }
        queued.cancel();
    }

    /** How long a cancel waits at most for the events from before it. */
    private static final long CATCH_UP_NANOS = java.util.concurrent.TimeUnit.SECONDS.toNanos(2);

    /** Ends it for a reason the inbox found (the container was destroyed, events were lost). */
    void endedBy(SubscriptionEnd reason) {
        queued.end(reason);
    }

    /** Called once when it ended for any reason: stop feeding it, and unregister unless done already. */
    void onEnd() {
        space.node().runInBackground(() -> {
            inbox.remove(this);
            if (unregistered.compareAndSet(false, true) && !space.node().isClosed()) {
                space.unregister(container, id);
            }
        });
    }
}
