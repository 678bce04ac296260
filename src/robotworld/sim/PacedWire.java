package robotworld.sim;

import java.io.IOException;
import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import robotworld.bus.LinkClosedException;
import robotworld.bus.SerialLink;

/**
 * The device end of a serial line with the timing of a real one. TCP and ptys deliver bytes at once; a 4800-baud
 * line takes about 2 ms per character in each direction. So every incoming byte is stamped with the moment its
 * last bit would have arrived (one character time after the previous byte finished, or after it was read) and is
 * handed over no earlier; every outgoing byte is written when its last bit would have left. With a character time
 * of zero nothing is delayed.
 */
final class PacedWire {

    private static final int END = -2;

    private record Inbound(int value, long readyAt) {
    }

    private final SerialLink link;
    private final long characterNanos;
    private final BlockingQueue<Inbound> inbound = new LinkedBlockingQueue<>();
    private final Thread reader;
    private volatile boolean closed;
    private long inboundFreeAt;
    private long outboundFreeAt;

    PacedWire(SerialLink link, Duration characterTime, String name) {
        this.link = link;
        this.characterNanos = characterTime.toNanos();
        this.reader = new Thread(this::readLoop, "cm11a-sim-reader " + name);
        reader.setDaemon(true);
        reader.start();
    }

    private void readLoop() {
        byte[] buffer = new byte[256];
        try {
            while (!closed) {
                int n = link.read(buffer, 0, buffer.length, Duration.ofMillis(200));
                long now = System.nanoTime();
                for (int i = 0; i < n; i++) {
                    inboundFreeAt = Math.max(now, inboundFreeAt) + characterNanos;
                    inbound.add(new Inbound(buffer[i] & 0xFF, inboundFreeAt));
                }
            }
        } catch (IOException e) {
            // the host went away: the session ends
        } finally {
            inbound.add(new Inbound(END, 0));
        }
    }

    /**
     * The next byte from the host, at the time it would have arrived, or -1 when none comes within
     * {@code timeout}.
     *
     * @throws LinkClosedException when the host has gone away
     */
    int receive(Duration timeout) throws IOException {
        Inbound next;
        try {
            next = inbound.poll(timeout.toNanos(), TimeUnit.NANOSECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new LinkClosedException(link.portName(), "interrupted");
        }
        if (next == null) {
            return -1;
        }
        if (next.value() == END) {
            inbound.add(next); // keep reporting the end
            throw new LinkClosedException(link.portName(), "the host went away");
        }
        sleepUntil(next.readyAt());
        return next.value();
    }

    /** Sends bytes to the host, each when it would have finished on the line. */
    void send(byte[] bytes) throws IOException {
        if (characterNanos == 0) {
            link.write(bytes);
            return;
        }
        // the characters of one answer leave back to back, as from a UART: a late wake-up for one byte
        // must not push the following ones back
        outboundFreeAt = Math.max(System.nanoTime(), outboundFreeAt);
        for (byte b : bytes) {
            outboundFreeAt += characterNanos;
            sleepUntil(outboundFreeAt);
            link.write(b & 0xFF);
        }
    }

    /** Waits until {@code nanoTime} is reached (precise to well under a millisecond on Linux). */
    static void sleepUntil(long nanoTime) {
        long left;
        while ((left = nanoTime - System.nanoTime()) > 0) {
            LockSupport.parkNanos(left);
        }
    }

    void close() {
        closed = true;
        try {
            link.close();
        } catch (IOException e) {
            // already gone
        }
    }
}
