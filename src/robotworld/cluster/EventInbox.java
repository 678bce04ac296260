package robotworld.cluster;

import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.TreeMap;

import robotworld.space.ContainerRef;
import robotworld.space.Notification;
import robotworld.space.Operation;
import robotworld.space.SpaceException;
import robotworld.space.SubscriptionEnd;

/**
 * The events of one container arriving at one member, put back into the container's order for the subscriptions
 * made on this member. Events come from whichever member made each call, so they may arrive out of order or (if
 * that member died before passing them on) not at all; each names its predecessor, so the inbox holds back what
 * arrives early and, if a predecessor does not come soon, reads the missing events from the container's journal.
 * If the journal no longer has them, the subscriptions end with {@link SubscriptionEnd#OVERFLOWED}: the listener
 * has every notification up to that point, in order, and knows that later ones may be missing.
 */
final class EventInbox {

    private static final System.Logger LOG = System.getLogger(EventInbox.class.getName());
    /** How long an early event waits for its predecessor before the journal is read. */
    private static final long REPAIR_DELAY_MILLIS = 100;

    private final ClusterSpace space;
    private final String container;
    private final ContainerRef ref;
    /** The last event delivered, or -1 before the first subscription's starting point is known. */
    private long last = -1;
    /** Events that arrived before their predecessor, by the sequence of that predecessor. */
    private final TreeMap<Long, Event> early = new TreeMap<>();
    private final List<ClusterSubscription> subscriptions = new ArrayList<>();
    /** Subscriptions being registered with the container: the inbox must stay (and keep events) meanwhile. */
    private int opening;
    private boolean repairScheduled;

    EventInbox(ClusterSpace space, String container, ContainerRef ref) {
        this.space = space;
        this.container = container;
        this.ref = ref;
    }

    /** A subscription is about to be registered: keep what arrives until it is. */
    synchronized boolean opening() {
        if (opening < 0) {
            return false; // closed: the caller makes a new inbox
        }
        opening++;
        return true;
    }

    /**
     * The subscription is registered: it sees the events after {@code sequence}; the container's chain continues
     * from {@code chainTail}.
     */
    synchronized void opened(ClusterSubscription subscription, long chainTail) {
        opening--;
        if (last < 0 || subscriptions.isEmpty()) {
            last = Math.max(last, chainTail);
        }
        subscriptions.add(subscription);
        deliverInOrder();
    }

    synchronized void openFailed() {
        opening--;
        closeIfUnused();
    }

    /** Events passed on by the member that made the calls. */
    synchronized void receive(List<Event> events) {
        for (Event event : events) {
            if (last < 0 || event.sequence() > last) {
                early.put(event.previous(), event);
            }
        }
        deliverInOrder();
    }

    private void deliverInOrder() {
        if (last < 0) {
            return;
        }
        early.headMap(last).clear(); // already delivered, or from before the subscriptions started
        Event next;
        while ((next = early.remove(last)) != null) {
            deliver(next);
            if (subscriptions.isEmpty() && opening == 0) {
                return; // the container was destroyed
            }
        }
        if (!early.isEmpty()) {
            scheduleRepair(REPAIR_DELAY_MILLIS);
        }
    }

    private void deliver(Event event) {
        last = event.sequence();
        Notification notification = null;
        for (ClusterSubscription subscription : subscriptions) {
            if (event.sequence() > subscription.from() && subscription.queued().wants(event.operation())) {
                if (notification == null) {
                    notification = new Notification(ref, event.operation(), event.entries(), event.displaced(),
                            event.sequence());
                }
                subscription.queued().offer(notification);
            }
        }
        if (event.operation() == Operation.DESTROY_CONTAINER) {
            endAll(SubscriptionEnd.CONTAINER_DESTROYED);
        }
    }

    private void endAll(SubscriptionEnd reason) {
        List<ClusterSubscription> ending = new ArrayList<>(subscriptions);
        subscriptions.clear();
        early.clear();
        for (ClusterSubscription subscription : ending) {
            subscription.endedBy(reason);
        }
        closeIfUnused();
    }

    /**
     * Returns once every event up to sequence {@code upTo} has been delivered (reading what is missing from the
     * journal), the subscriptions have ended, or {@code deadline} ({@link System#nanoTime()}) has passed.
     */
    void awaitDelivered(long upTo, long deadline) {
        while (true) {
            synchronized (this) {
                if (last >= upTo || subscriptions.isEmpty()) {
                    return;
                }
                try {
                    wait(10); // a message on its way may bring them
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
                if (last >= upTo) {
                    return;
                }
            }
            if (System.nanoTime() - deadline >= 0) {
                return;
            }
            repair();
        }
    }

    /** A subscription ended: it no longer gets events. */
    synchronized void remove(ClusterSubscription subscription) {
        subscriptions.remove(subscription);
        closeIfUnused();
    }

    private void closeIfUnused() {
        if (subscriptions.isEmpty() && opening == 0) {
            opening = -1;
            space.node().removeInbox(space.name(), container, this);
        }
    }

    private void scheduleRepair(long delayMillis) {
        if (!repairScheduled) {
            repairScheduled = true;
            space.node().schedule(this::repair, delayMillis);
        }
    }

    /**
     * Compares the chain with the container's journal and delivers what is missing; ends the subscriptions with
     * a gap signal if the journal cannot close the gap (or the container no longer knows them).
     */
    void repair() {
        long after;
        List<OpId> registered = new ArrayList<>();
        synchronized (this) {
            repairScheduled = false;
            if (last < 0 || subscriptions.isEmpty()) {
                return;
            }
            after = last;
            for (ClusterSubscription subscription : subscriptions) {
                registered.add(subscription.id());
            }
        }
        Outcome journal;
        try {
            journal = space.readJournal(container, after, registered);
        } catch (SpaceException e) {
            synchronized (this) {
                if (!subscriptions.isEmpty()) {
                    scheduleRepair(1_000); // the cluster is busy recovering; the chain waits
                }
            }
            LOG.log(Level.DEBUG, "could not read the journal of " + container + ": " + e.getMessage());
            return;
        }
        synchronized (this) {
            if (journal.status == Outcome.Status.NOT_FOUND || journal.status == Outcome.Status.DESTROYED
                    && journal.events.isEmpty()) {
                LOG.log(Level.WARNING, "container " + container + " is gone; its subscriptions on this member end");
                endAll(SubscriptionEnd.CONTAINER_DESTROYED);
                return;
            }
            if (last != after) {
                // events arrived meanwhile: what the journal says may be old news; look again if still needed
                receive(journal.events);
                return;
            }
            if (!journal.complete) {
                LOG.log(Level.WARNING, "subscriptions on " + container + " missed events after sequence " + after
                        + " (a cluster member failed and the journal no longer holds them); they end as overflowed");
                endAll(SubscriptionEnd.OVERFLOWED);
                return;
            }
            for (Iterator<Event> it = journal.events.iterator(); it.hasNext(); ) {
                Event event = it.next();
                early.put(event.previous(), event);
            }
            deliverInOrder();
        }
    }
}
