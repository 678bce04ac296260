package robotworld.space.remote;

import java.lang.System.Logger.Level;
import java.util.EnumSet;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

import robotworld.space.ContainerRef;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/**
 * The client side of a subscription: receives its notifications from the stream reader in order, queues them
 * (bounded, like the embedded space: a full queue ends the subscription as {@link SubscriptionEnd#OVERFLOWED})
 * and delivers them to the listener on a delivery thread, one at a time. It also remembers what it needs to be
 * re-established on a new stream: its parameters, when its timeout runs out, and the container sequence up to
 * which it is complete.
 */
final class RemoteSubscription implements Subscription {

    private static final System.Logger LOG = System.getLogger(RemoteSubscription.class.getName());

    final ContainerRef container;
    final Set<Operation> operations;
    final NotificationMode mode;
    final Timeout timeout;
    private final NotificationListener listener;
    private final BlockingQueue<Notification> queue;
    private final Executor delivery;
    private final Canceller canceller;
    private final AtomicBoolean draining = new AtomicBoolean();
    private final AtomicBoolean cancelRequested = new AtomicBoolean();
    private final long startNanos = System.nanoTime();
    private volatile long lastFiredNanos = startNanos;
    /** How many notifications came: a PROLONG period the client ends itself checks whether one came meanwhile. */
    private final AtomicLong firings = new AtomicLong();

    /** The server's id of this subscription on the current stream, or null while it is not established. */
    volatile String serverId;
    /** The session {@link #serverId} belongs to. */
    volatile String session;
    /** The container's sequence up to which this subscription has seen every matching operation. */
    volatile long completeUpTo;

    private volatile SubscriptionEnd endReason;
    private boolean endDelivered;

    /** Asks the server to stop a subscription. */
    interface Canceller {
        void cancel(RemoteSubscription subscription);
    }

    RemoteSubscription(ContainerRef container, Set<Operation> operations, NotificationMode mode, Timeout timeout,
                       NotificationListener listener, int queueCapacity, Executor delivery, Canceller canceller) {
        this.container = container;
        this.operations = operations.isEmpty() ? EnumSet.noneOf(Operation.class) : EnumSet.copyOf(operations);
        this.mode = mode;
        this.timeout = timeout;
        this.listener = listener;
        this.queue = new LinkedBlockingQueue<>(queueCapacity);
        this.delivery = delivery;
        this.canceller = canceller;
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
        if (endReason == null && cancelRequested.compareAndSet(false, true)) {
            canceller.cancel(this); // the server's end frame (after what happened before) completes it
        }
    }

    boolean cancelRequested() {
        return cancelRequested.get();
    }

    /** A notification from the stream, in order. */
    void offer(Notification notification) {
        if (endReason != null) {
            return;
        }
        completeUpTo = Math.max(completeUpTo, notification.sequence());
        lastFiredNanos = System.nanoTime();
        firings.incrementAndGet();
        if (!queue.offer(notification)) {
            overflowed();
            return;
        }
        scheduleDrain();
    }

    /** Notifications were dropped: the listener is told that events may be missing, and the server stops sending. */
    void overflowed() {
        end(SubscriptionEnd.OVERFLOWED);
        canceller.cancel(this);
    }

    /** Ends the subscription (first reason wins); queued notifications are delivered first. */
    void end(SubscriptionEnd reason) {
        synchronized (this) {
            if (endReason != null) {
                return;
            }
            endReason = reason;
        }
        scheduleDrain();
    }

    /**
     * The timeout to ask the server for when establishing this subscription (again), or null if it has run out
     * meanwhile. {@code ONCE} and {@code RESTRICTED}: what is left of it, as it counts from subscribing.
     * {@code PROLONG}: the whole timeout, because the server restarts the timeout it was given at every firing;
     * asking for what is left of the current period would shorten every later period, and the subscription would
     * expire before a full timeout had passed without a firing. What is left of the current period is kept by the
     * client ({@link #established}).
     */
    Timeout timeoutOnServer() {
        Timeout left = remainingTimeout();
        if (left == null || mode != NotificationMode.PROLONG || timeout.isInfinite()) {
            return left;
        }
        return timeout;
    }

    /**
     * The subscription was established on the server. For {@code PROLONG} the server's clock has just started with
     * the whole timeout, though the current period began earlier (on subscribing, or at the last notification
     * before the stream broke): if nothing fires in what is left of it, the client ends the subscription as
     * {@link SubscriptionEnd#EXPIRED} then, as the period's end, and takes it off the server.
     */
    void established(ScheduledExecutorService timer) {
        if (mode != NotificationMode.PROLONG || timeout.isInfinite()) {
            return;
        }
        long period = firings.get();
        Timeout left = remainingTimeout(); // rounded up to whole milliseconds: never ends the period early
        if (left == null) {
            return; // the server was given no time either: it ends the subscription itself
        }
        try {
            timer.schedule(() -> expireIfNothingFiredSince(period), left.millis(), TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException closing) {
            // the space is closing: the subscription ends with it
        }
    }

    private void expireIfNothingFiredSince(long period) {
        if (endReason != null || firings.get() != period) {
            return; // ended, or fired meanwhile: the server's clock, restarted at that firing, goes on
        }
        end(SubscriptionEnd.EXPIRED);
        try {
            delivery.execute(() -> canceller.cancel(this)); // a call to the server: not on the timer thread
        } catch (RejectedExecutionException closing) {
            // the space is closing: its subscriptions end with it on the server too
        }
    }

    /**
     * What is left of this subscription's timeout, or null if it has run out: since subscribing, or for
     * {@code PROLONG} since the last notification.
     */
    Timeout remainingTimeout() {
        if (mode == NotificationMode.INFINITE || timeout.isInfinite()) {
            return timeout;
        }
        long from = mode == NotificationMode.PROLONG ? lastFiredNanos : startNanos;
        long left = timeout.millis() - TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - from);
        return left <= 0 ? null : Timeout.ofMillis(left);
    }

    private void scheduleDrain() {
        if (draining.compareAndSet(false, true)) {
            try {
                delivery.execute(this::drain);
            } catch (RejectedExecutionException closing) {
                drain(); // the space is closing and its delivery threads are gone: the listener still hears the end
            }
        }
    }

    private void drain() {
        do {
            Notification next;
            while ((next = queue.poll()) != null) {
                try {
                    listener.onNotification(next);
                } catch (RuntimeException e) {
                    LOG.log(Level.WARNING, "notification listener failed on " + next.operation() + " of " + container, e);
                }
            }
            SubscriptionEnd reason = endReason;
            if (reason != null && queue.isEmpty() && !endDelivered) {
                endDelivered = true;
                try {
                    listener.onEnd(reason);
                } catch (RuntimeException e) {
                    LOG.log(Level.WARNING, "notification listener failed on end (" + reason + ") of " + container, e);
                }
            }
            draining.set(false);
        } while ((!queue.isEmpty() || (endReason != null && !endDelivered)) && draining.compareAndSet(false, true));
    }
}
