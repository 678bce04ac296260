package robotworld.x10;

import java.io.IOException;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.LinkClosedException;

/**
 * The one thread that talks to the CM11A. Commands from any number of threads queue up here and run one after
 * the other, so frames never interleave on the wire; between commands the thread looks for polls, so uploads and
 * power-fail requests are answered even when nobody sends anything.
 *
 * <p>A lost link (closed connection, unplugged adapter) is opened again: before the next command, and while idle
 * every so often (backing off to {@link #MAX_RECONNECT_PAUSE_MILLIS}), so uploads resume when the interface is back
 * even if nobody sends. A command meanwhile fails at once with {@link X10Exception} naming the cause. A network link
 * that went silent (an interface that answered nothing until the dead-interface timeout) may be a dead connection
 * that was never closed, such as a serial bridge that crashed or was cut off: it is opened again before the next
 * command too.
 */
final class LinkWorker {

    private static final Logger LOG = LoggerFactory.getLogger(LinkWorker.class);

    /** Work for the link thread. */
    @FunctionalInterface
    interface Job<T> {
        T run(CM11aProtocol protocol) throws IOException;
    }

    private record Queued<T>(Job<T> job, CompletableFuture<T> result) {
        void run(CM11aProtocol protocol) {
            try {
                result.complete(job.run(protocol));
            } catch (Throwable e) {
                result.completeExceptionally(e);
            }
        }
    }

    private final CM11aProtocol protocol;
    private final CM11aConfig config;
    private final BlockingQueue<Queued<?>> queue = new LinkedBlockingQueue<>();
    /** Longest pause between two reconnection attempts while idle. */
    static final long MAX_RECONNECT_PAUSE_MILLIS = 2_000;
    private static final long FIRST_RECONNECT_PAUSE_MILLIS = 50;

    private final Thread thread;
    private volatile boolean closed;
    private volatile IOException linkFailure;
    /** The last command met a silent interface: the link may be dead without knowing it. */
    private volatile boolean linkSuspect;
    private long reconnectPauseMillis = FIRST_RECONNECT_PAUSE_MILLIS;
    private long nextIdleReconnect;

    LinkWorker(CM11aProtocol protocol, CM11aConfig config) {
        this.protocol = protocol;
        this.config = config;
        this.thread = new Thread(this::loop, "cm11a-link " + protocol.portName());
        thread.setDaemon(true);
        thread.start();
    }

    /** Queues a job; the future completes with its result or its exception. */
    <T> CompletableFuture<T> submit(Job<T> job) {
        CompletableFuture<T> result = new CompletableFuture<>();
        if (closed) {
            result.completeExceptionally(new X10Exception(protocol.portName(), "the controller is closed"));
            return result;
        }
        queue.add(new Queued<>(job, result));
        if (closed) {
            failQueued(); // close() may have drained the queue just before our add
        }
        return result;
    }

    private void loop() {
        while (!closed) {
            Queued<?> next;
            try {
                next = queue.poll(config.idlePollInterval().toNanos(), TimeUnit.NANOSECONDS);
            } catch (InterruptedException e) {
                break;
            }
            if (next != null) {
                if ((linkFailure != null || linkSuspect) && !reconnect()) {
                    next.result().completeExceptionally(new X10Exception(protocol.portName(),
                            "the link is broken and could not be opened again: " + linkFailure.getMessage(),
                            linkFailure));
                    continue;
                }
                next.run(protocol);
                noteFailure(next.result());
            } else if (linkFailure != null) {
                if (System.nanoTime() - nextIdleReconnect >= 0 && reconnect()) {
                    serviceIdle();
                }
            } else {
                serviceIdle();
            }
        }
        failQueued();
    }

    /** Opens the link again; true when it is open. Says so once when a lost link is back. */
    private boolean reconnect() {
        if (closed) {
            return false;
        }
        try {
            protocol.reopen();
        } catch (IOException e) {
            if (linkFailure == null) {
                linkFailed(e);
            } else {
                linkFailure = e;
            }
            nextIdleReconnect = System.nanoTime() + reconnectPauseMillis * 1_000_000;
            reconnectPauseMillis = Math.min(MAX_RECONNECT_PAUSE_MILLIS, reconnectPauseMillis * 2);
            LOG.debug("{}: reconnecting failed: {}", protocol.portName(), e.getMessage());
            return false;
        }
        if (linkFailure != null) {
            LOG.warn("{}: link back", protocol.portName());
        } else {
            LOG.info("{}: the interface was silent; the link was opened again", protocol.portName());
        }
        linkFailure = null;
        linkSuspect = false;
        reconnectPauseMillis = FIRST_RECONNECT_PAUSE_MILLIS;
        return true;
    }

    private void serviceIdle() {
        try {
            protocol.watchWhileIdle();
        } catch (LinkClosedException e) {
            linkFailed(e);
        } catch (IOException | RuntimeException e) {
            LOG.warn("{}: while answering a poll: {}", protocol.portName(), e.getMessage());
        }
    }

    private void noteFailure(CompletableFuture<?> result) {
        result.exceptionally(e -> {
            if (e instanceof LinkClosedException closedLink) {
                linkFailed(closedLink);
            } else if (e instanceof X10TimeoutException && protocol.silenceMayMeanADeadConnection()) {
                linkSuspect = true;
            }
            return null;
        });
    }

    private void linkFailed(IOException e) {
        if (!closed && linkFailure == null) {
            LOG.warn("{}: link lost: {}; reconnecting", protocol.portName(), e.getMessage());
            nextIdleReconnect = System.nanoTime();
        }
        linkFailure = e;
    }

    private void failQueued() {
        Queued<?> left;
        while ((left = queue.poll()) != null) {
            left.result().completeExceptionally(new X10Exception(protocol.portName(), "the controller is closed"));
        }
    }

    /** Asks the thread to stop after the running job; queued jobs fail. */
    void stop() {
        closed = true;
        thread.interrupt();
    }

    /** Waits up to {@code waitMillis} for the thread to end (after {@link #stop()}). */
    void join(long waitMillis) {
        try {
            thread.join(waitMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        failQueued();
    }
}
