package robotworld.space.internal;

import java.util.Arrays;
import java.util.List;

import robotworld.space.ContainerRef;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.Operation;
import robotworld.space.SubscriptionEnd;

/**
 * The subscriptions of one container. Publishing reads a copy-on-write array, so an operation on a container
 * nobody observes pays one volatile read.
 */
final class NotificationHub {

    private static final QueuedSubscription[] NONE = new QueuedSubscription[0];

    private final ContainerRef container;
    private volatile QueuedSubscription[] subscriptions = NONE;

    NotificationHub(ContainerRef container) {
        this.container = container;
    }

    synchronized void add(QueuedSubscription subscription) {
        QueuedSubscription[] current = subscriptions;
        QueuedSubscription[] grown = Arrays.copyOf(current, current.length + 1);
        grown[current.length] = subscription;
        subscriptions = grown;
    }

    synchronized void remove(QueuedSubscription subscription) {
        QueuedSubscription[] current = subscriptions;
        for (int i = 0; i < current.length; i++) {
            if (current[i] == subscription) {
                QueuedSubscription[] shrunk = new QueuedSubscription[current.length - 1];
                System.arraycopy(current, 0, shrunk, 0, i);
                System.arraycopy(current, i + 1, shrunk, i, current.length - i - 1);
                subscriptions = shrunk;
                return;
            }
        }
    }

    int count() {
        return subscriptions.length;
    }

    /** Offers one operation to every subscription that asked for it; call in operation order. */
    void publish(Operation operation, List<Entry> entries, List<Entry> displaced, long sequence) {
        QueuedSubscription[] current = subscriptions;
        if (current.length == 0) {
            return;
        }
        Notification notification = null;
        for (QueuedSubscription subscription : current) {
            if (subscription.wants(operation)) {
                if (notification == null) {
                    notification = new Notification(container, operation, entries, displaced, sequence);
                }
                subscription.offer(notification);
            }
        }
    }

    /** Ends every subscription. */
    void endAll(SubscriptionEnd reason) {
        for (QueuedSubscription subscription : subscriptions) {
            subscription.end(reason);
        }
    }
}
