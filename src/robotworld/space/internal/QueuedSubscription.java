package robotworld.space.internal;

import java.lang.System.Logger.Level;
import java.util.EnumSet;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;

import robotworld.space.ContainerRef;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/**
 * One subscription: decides which operations it reports and when it ends (mode and timeout), and hands the
 * notifications to its listener through a bounded queue drained by one delivery task at a time.
 *
 * <p>{@link #offer} runs inside the container's critical section, in operation order, and never blocks: when
 * the queue is full the subscription ends as {@link SubscriptionEnd#OVERFLOWED}, so the listener learns exactly
 * where its stream stops instead of silently missing notifications in the middle of it.
 *
 * <p>The clustered space uses it too: there {@code offer} is called in operation order by the member that receives
 * the container's notifications.
 */
public final class QueuedSubscription implements Subscription {

    private static final System.Logger LOG = System.getLogger(QueuedSubscription.class.getName());

    private final ContainerRef container;
    private final Set<Operation> operations;
    private final NotificationMode mode;
    private final long timeoutNanos;
    private final NotificationListener listener;
    private final BlockingQueue<Notification> queue;
    private final Delivery delivery;
    private final Consumer<QueuedSubscription> onEnd;
    private final AtomicBoolean draining = new AtomicBoolean();

    /** Set once, under this object's lock, after the last notification was queued. */
    private volatile SubscriptionEnd endReason;
    /** Touched only by the (serialised) drain task. */
    private boolean endDelivered;
    private long deadline;
    private ScheduledFuture<?> expiry;

    /**
     * A subscription that is not yet running; call {@link #start()}.
     *
     * @param onEnd called once, inside {@link #end}, when the subscription ends for any reason
     */
    public QueuedSubscription(ContainerRef container, Set<Operation> operations, NotificationMode mode, Timeout timeout,
                       NotificationListener listener, int queueCapacity, Delivery delivery,
                       Consumer<QueuedSubscription> onEnd) {
        this.container = container;
        this.operations = operations.isEmpty() ? EnumSet.noneOf(Operation.class) : EnumSet.copyOf(operations);
        this.mode = mode;
        this.timeoutNanos = mode == NotificationMode.INFINITE || timeout.isInfinite()
                ? -1 : TimeUnit.MILLISECONDS.toNanos(timeout.millis());
        this.listener = listener;
        this.queue = new LinkedBlockingQueue<>(queueCapacity);
        this.delivery = delivery;
        this.onEnd = onEnd;
    }

    /** Starts the timeout clock. */
    public synchronized void start() {
        if (timeoutNanos >= 0) {
            deadline = System.nanoTime() + timeoutNanos;
            expiry = delivery.schedule(this::expireIfDue, timeoutNanos);
        }
    }

    @Override
    public ContainerRef container() {
        return container;
    }

    @Override
    public boolean isActive() {
        return endReason == null;
    }

    @Override
    public void cancel() {
        end(SubscriptionEnd.CANCELLED);
    }

    public boolean wants(Operation operation) {
        return endReason == null && operations.contains(operation);
    }

    /** Queues a notification; called in operation order from the container's critical section. */
    public synchronized void offer(Notification notification) {
        if (endReason != null) {
            return;
        }
        if (timeoutNanos >= 0 && System.nanoTime() - deadline >= 0) {
            end(SubscriptionEnd.EXPIRED); // the timer has not run yet, but the time is up
            return;
        }
        if (!queue.offer(notification)) {
            end(SubscriptionEnd.OVERFLOWED);
            return;
        }
        if (mode == NotificationMode.ONCE) {
            end(SubscriptionEnd.FIRED_ONCE);
            return;
        }
        if (mode == NotificationMode.PROLONG && timeoutNanos >= 0) {
            deadline = System.nanoTime() + timeoutNanos; // the timer re-arms itself when it sees this
        }
        scheduleDrain();
    }

    /** Ends the subscription (first reason wins); queued notifications are still delivered, then the reason. */
    public synchronized void end(SubscriptionEnd reason) {
        if (endReason != null) {
            return;
        }
        endReason = reason;
        if (expiry != null) {
            expiry.cancel(false);
        }
        onEnd.accept(this);
        scheduleDrain();
    }

    private synchronized void expireIfDue() {
        if (endReason != null) {
            return;
        }
        long left = deadline - System.nanoTime();
        if (left <= 0) {
            end(SubscriptionEnd.EXPIRED);
        } else {
            expiry = delivery.schedule(this::expireIfDue, left); // prolonged meanwhile
        }
    }

    private void scheduleDrain() {
        if (draining.compareAndSet(false, true)) {
            delivery.execute(this::drain);
        }
    }

    private void drain() {
        do {
            Notification next;
            while ((next = queue.poll()) != null) {
                deliver(next);
            }
            SubscriptionEnd reason = endReason;
            // reading endReason first makes the emptiness check final: nothing is queued after the end
            if (reason != null && queue.isEmpty() && !endDelivered) {
                endDelivered = true;
                deliverEnd(reason);
            }
            draining.set(false);
        } while (hasWork() && draining.compareAndSet(false, true));
    }

    private boolean hasWork() {
        return !queue.isEmpty() || (endReason != null && !endDelivered);
    }

    private void deliver(Notification notification) {
        try {
            listener.onNotification(notification);
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "notification listener failed on " + notification.operation() + " of " + container, e);
        }
    }

    private void deliverEnd(SubscriptionEnd reason) {
        try {
            listener.onEnd(reason);
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "notification listener failed on end (" + reason + ") of " + container, e);
        }
    }
}
