package robotworld.bus;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.Deque;

/**
 * Two in-memory {@link SerialLink}s connected to each other, for protocol tests that script one side byte by
 * byte without sockets or ptys. Closing either end ends both.
 */
public final class LinkPair {

    private final Channel toB = new Channel();
    private final Channel toA = new Channel();
    private final End a = new End("memory-a", toA, toB);
    private final End b = new End("memory-b", toB, toA);

    /** One end (e.g. the host). */
    public SerialLink a() {
        return a;
    }

    /** The other end (e.g. the device). */
    public SerialLink b() {
        return b;
    }

    private final class Channel {
        private final Deque<Byte> bytes = new ArrayDeque<>();
        private boolean closed;

        synchronized void put(byte[] data) throws IOException {
            if (closed) {
                throw new LinkClosedException("memory", "closed");
            }
            for (byte value : data) {
                bytes.addLast(value);
            }
            notifyAll();
        }

        synchronized int take(byte[] buffer, int offset, int length, Duration timeout) throws IOException {
            long deadline = System.nanoTime() + timeout.toNanos();
            while (bytes.isEmpty() && !closed) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    return 0;
                }
                try {
                    wait(Math.max(1, left / 1_000_000), 0);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return 0;
                }
            }
            if (bytes.isEmpty()) {
                throw new LinkClosedException("memory", "the other end closed");
            }
            int n = 0;
            while (n < length && !bytes.isEmpty()) {
                buffer[offset + n++] = bytes.removeFirst();
            }
            return n;
        }

        synchronized int available() {
            return bytes.size();
        }

        synchronized void close() {
            closed = true;
            notifyAll();
        }
    }

    private final class End implements SerialLink {
        private final String name;
        private final Channel in;
        private final Channel out;
        private volatile boolean open = true;

        End(String name, Channel in, Channel out) {
            this.name = name;
            this.in = in;
            this.out = out;
        }

        @Override
        public String portName() {
            return name;
        }

        @Override
        public void open() {
        }

        @Override
        public boolean isOpen() {
            return open;
        }

        @Override
        public void write(byte[] bytes) throws IOException {
            out.put(bytes);
        }

        @Override
        public int read(byte[] buffer, int offset, int length, Duration timeout) throws IOException {
            return in.take(buffer, offset, length, timeout);
        }

        @Override
        public int available() {
            return in.available();
        }

        @Override
        public void close() {
            open = false;
            toA.close();
            toB.close();
        }
    }
}
