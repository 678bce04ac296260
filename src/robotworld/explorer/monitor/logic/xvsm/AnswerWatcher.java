package robotworld.explorer.monitor.logic.xvsm;

import java.time.Duration;
import java.time.Instant;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceException;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;
import robotworld.xvsm.CallTuple;
import robotworld.xvsm.MalformedCallException;
import robotworld.xvsm.XVSMModule;

/**
 * Subscribes to one module's {@code <Participant><Module>ANSWER} container and hands every answer written or
 * shifted into it to an {@link AnswerListener}. Every local call the module's host publishes and every answered
 * remote call is such a shift (docs/runtime.md), so this sees all activity of the module.
 *
 * <p>The container is looked up or created, so monitoring may start before the module's program. What it
 * already holds (the latest published call of each host, answers not yet collected) is handed over first, oldest
 * first, as {@link AnswerListener#earlier}: a monitor started late still shows the module's last known state. An
 * answer arriving in the moment between that read and the subscription can be missed; the next one brings the
 * monitor up to date. A subscription that overflowed or whose container was destroyed is renewed; only a closed
 * space ends watching.
 *
 * <p>Watching starts with {@link #start()} (on the calling thread: it talks to the space) or
 * {@link #startInBackground()} (for the Swing thread, which must not wait for the network).
 */
public final class AnswerWatcher implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(AnswerWatcher.class);
    private static final Set<Operation> PUBLISHING = Set.of(Operation.WRITE, Operation.SHIFT);

    private final Capi space;
    private final ContainerSpec spec;
    private final AnswerListener listener;
    private final CountDownLatch startAttempted = new CountDownLatch(1);
    private volatile boolean watching;
    private Subscription subscription;
    private boolean closed;

    /** A watcher of one module's answers; it watches once started. */
    public AnswerWatcher(Capi space, String participant, String moduleName, AnswerListener listener) {
        this.space = space;
        // the spec XVSMModule's containers are created with (robotworld.xvsm.ModuleContainers): LIFO, KEY view
        this.spec = ContainerSpec.of(Order.LIFO).withKeyView().unbounded()
                .named(XVSMModule.answerContainerName(participant, moduleName));
        this.listener = listener;
    }

    /**
     * Hands over what the container holds, then subscribes; on this thread.
     *
     * @return this watcher
     * @throws SpaceException when the space cannot be reached
     */
    public AnswerWatcher start() {
        try {
            ContainerRef answers = space.lookupOrCreateContainer(spec);
            if (!isClosed()) {
                handOverEarlierAnswers(answers);
            }
            subscribe(answers);
            watching = !isClosed();
            return this;
        } finally {
            startAttempted.countDown();
        }
    }

    /**
     * Starts on a background thread; a failure reaches the listener as {@link AnswerListener#stopped}.
     *
     * @return this watcher
     */
    public AnswerWatcher startInBackground() {
        Starter.THREADS.execute(() -> {
            try {
                start();
            } catch (RuntimeException e) { // a SpaceException, or an answer the listener choked on
                listener.stopped("cannot watch " + spec.name() + ": " + e.getMessage());
            }
        });
        return this;
    }

    /**
     * Waits until the start has been tried.
     *
     * @return whether this watcher watches (false: the start failed, or is still under way after {@code timeout})
     */
    public boolean awaitWatching(Duration timeout) throws InterruptedException {
        return startAttempted.await(timeout.toMillis(), TimeUnit.MILLISECONDS) && watching;
    }

    /** The threads that start watchers in the background; daemons, so they never keep a program alive. */
    private static final class Starter {
        static final ExecutorService THREADS = Executors.newCachedThreadPool(task -> {
            Thread thread = new Thread(task, "monitor-start");
            thread.setDaemon(true);
            return thread;
        });
    }

    private void handOverEarlierAnswers(ContainerRef answers) {
        for (Entry entry : space.read(answers, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL))) {
            try {
                listener.earlier(CallTuple.parse(entry));
            } catch (MalformedCallException e) {
                LOG.debug("{}: ignoring an entry that is not an answer: {}", spec.name(), entry);
            }
        }
    }

    /** The ANSWER container's name. */
    public String containerName() {
        return spec.name();
    }

    private synchronized void subscribe(ContainerRef answers) {
        if (closed) {
            return;
        }
        subscription = space.subscribe(answers, PUBLISHING, NotificationMode.INFINITE, Timeout.INFINITE,
                new Forwarder());
    }

    @Override
    public synchronized void close() {
        closed = true;
        if (subscription != null) {
            subscription.cancel();
        }
    }

    private synchronized boolean isClosed() {
        return closed;
    }

    /** Turns notifications into answers, and renews the subscription when it ends early. */
    private final class Forwarder implements NotificationListener {

        @Override
        public void onNotification(Notification notification) {
            Instant now = Instant.now();
            for (Entry entry : notification.entries()) {
                try {
                    listener.answer(CallTuple.parse(entry), now);
                } catch (MalformedCallException e) {
                    LOG.debug("{}: ignoring an entry that is not an answer: {}", spec.name(), entry);
                }
            }
        }

        @Override
        public void onEnd(SubscriptionEnd reason) {
            if (isClosed() || reason == SubscriptionEnd.CANCELLED) {
                return;
            }
            if (reason == SubscriptionEnd.OVERFLOWED || reason == SubscriptionEnd.CONTAINER_DESTROYED) {
                try {
                    subscribe(space.lookupOrCreateContainer(spec)); // a few answers may be missed; the next one brings the panel up to date
                    return;
                } catch (SpaceException e) {
                    listener.stopped("cannot watch " + spec.name() + " again: " + e.getMessage());
                    return;
                }
            }
            listener.stopped(reason == SubscriptionEnd.SPACE_CLOSED ? "the space connection closed"
                    : "watching ended: " + reason);
        }
    }
}
