package robotworld.safety;

import java.util.Set;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.space.Capi;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.SpaceException;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/**
 * Hands every {@link StopRecord} published from now on in a space to a listener, on a thread of the space: what
 * monitors use to show why an actuator stopped. A subscription that overflowed or whose container was destroyed is
 * renewed (a few records may be missed then); only a closed space or {@link #close()} ends watching.
 */
public final class StopWatcher implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(StopWatcher.class);
    private static final Set<Operation> PUBLISHING = Set.of(Operation.WRITE, Operation.SHIFT);

    private final Capi space;
    private final Consumer<StopRecord> listener;
    private Subscription subscription;
    private boolean closed;

    private StopWatcher(Capi space, Consumer<StopRecord> listener) {
        this.space = space;
        this.listener = listener;
    }

    /**
     * Starts watching, on this thread.
     *
     * @throws SpaceException when the space cannot be reached
     */
    public static StopWatcher start(Capi space, Consumer<StopRecord> listener) {
        StopWatcher watcher = new StopWatcher(space, listener);
        watcher.subscribe();
        return watcher;
    }

    private synchronized void subscribe() {
        if (closed) {
            return;
        }
        subscription = space.subscribe(SafetyContainers.stops(space), PUBLISHING, NotificationMode.INFINITE,
                Timeout.INFINITE, new NotificationListener() {
                    @Override
                    public void onNotification(Notification notification) {
                        for (Entry entry : notification.entries()) {
                            try {
                                listener.accept(StopRecord.parse(entry));
                            } catch (IllegalArgumentException e) {
                                LOG.debug("ignoring an entry that is not a stop record: {}", entry);
                            }
                        }
                    }

                    @Override
                    public void onEnd(SubscriptionEnd reason) {
                        if (reason == SubscriptionEnd.OVERFLOWED || reason == SubscriptionEnd.CONTAINER_DESTROYED) {
                            try {
                                subscribe();
                            } catch (SpaceException e) {
                                LOG.warn("cannot watch stop records again: {}", e.toString());
                            }
                        }
                    }
                });
    }

    @Override
    public synchronized void close() {
        closed = true;
        if (subscription != null) {
            subscription.cancel();
        }
    }
}
