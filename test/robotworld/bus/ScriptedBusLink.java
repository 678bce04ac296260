package robotworld.bus;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

/**
 * An in-memory {@link SerialLink} whose far end is a script: every frame written is handed to a responder that
 * returns the chunks to deliver back (none = silence). Lets tests produce exact byte-level situations.
 */
final class ScriptedBusLink implements SerialLink {

    private final BlockingQueue<byte[]> inbound = new LinkedBlockingQueue<>();
    private final List<byte[]> written = new ArrayList<>();
    private Function<byte[], List<byte[]>> responder;
    private byte[] partial;
    private boolean open;
    private int opens;
    private boolean failNextWrite;

    ScriptedBusLink(Function<byte[], List<byte[]>> responder) {
        this.responder = responder;
    }

    synchronized void respondWith(Function<byte[], List<byte[]>> newResponder) {
        this.responder = newResponder;
    }

    /** Queues bytes as if they had arrived unasked. */
    void inject(byte[] bytes) {
        inbound.add(bytes.clone());
    }

    synchronized List<byte[]> written() {
        return List.copyOf(written);
    }

    synchronized int opens() {
        return opens;
    }

    /** The next write fails as if the peer had gone away. */
    synchronized void failNextWrite() {
        failNextWrite = true;
    }

    @Override
    public String portName() {
        return "script://bus";
    }

    @Override
    public synchronized void open() {
        open = true;
        opens++;
    }

    @Override
    public synchronized boolean isOpen() {
        return open;
    }

    @Override
    public void write(byte[] bytes) throws IOException {
        List<byte[]> reply;
        synchronized (this) {
            if (failNextWrite) {
                failNextWrite = false;
                open = false;
                throw new LinkClosedException(portName(), "the peer went away");
            }
            written.add(bytes.clone());
            reply = responder.apply(bytes.clone());
        }
        inbound.addAll(reply);
    }

    @Override
    public int read(byte[] buffer, int offset, int length, Duration timeout) throws IOException {
        byte[] chunk = partial;
        partial = null;
        if (chunk == null) {
            try {
                chunk = timeout.isZero() ? inbound.poll() : inbound.poll(timeout.toNanos(), TimeUnit.NANOSECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new LinkClosedException(portName(), "interrupted");
            }
            if (chunk == null) {
                return 0;
            }
        }
        int n = Math.min(length, chunk.length);
        System.arraycopy(chunk, 0, buffer, offset, n);
        if (n < chunk.length) {
            partial = java.util.Arrays.copyOfRange(chunk, n, chunk.length);
        }
        return n;
    }

    @Override
    public int available() {
        byte[] next = partial != null ? partial : inbound.peek();
        return next == null ? 0 : next.length;
    }

    @Override
    public synchronized void close() {
        open = false;
    }
}
