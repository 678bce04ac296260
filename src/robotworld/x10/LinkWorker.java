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
    private final Thread thread;
    private volatile boolean closed;
    private volatile IOException linkFailure;

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
            if (linkFailure != null) {
                if (next != null) {
                    next.result().completeExceptionally(new X10Exception(protocol.portName(),
                            "the link is broken: " + linkFailure.getMessage(), linkFailure));
                }
                continue;
            }
            if (next != null) {
                next.run(protocol);
                noteLinkFailure(next.result());
            } else {
                serviceIdle();
            }
        }
        failQueued();
    }

    private void serviceIdle() {
        try {
            protocol.serviceIdle();
        } catch (LinkClosedException e) {
            linkFailed(e);
        } catch (IOException | RuntimeException e) {
            LOG.warn("{}: while answering a poll: {}", protocol.portName(), e.getMessage());
        }
    }

    private void noteLinkFailure(CompletableFuture<?> result) {
        result.exceptionally(e -> {
            if (e instanceof LinkClosedException closedLink) {
                linkFailed(closedLink);
            }
            return null;
        });
    }

    private void linkFailed(IOException e) {
        if (!closed && linkFailure == null) {
            LOG.warn("{}: link lost: {}", protocol.portName(), e.getMessage());
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
