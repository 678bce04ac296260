package robotworld.bus;

import com.fazecast.jSerialComm.SerialPort;
import java.io.IOException;
import java.time.Duration;
import java.util.concurrent.locks.LockSupport;

/**
 * A {@link SerialLink} over a local serial device through jSerialComm. Also opens pseudo-terminals (e.g. the links
 * of a {@code socat pty,rawer,link=A pty,rawer,link=B} pair), which is how tests exercise this path.
 *
 * <p>Modem lines (DTR, RTS, CTS, RI) are neither used nor required: ptys have none and a CM11A needs none.
 *
 * <p>Closing waits for the calls into the port that are under way on other threads (a read ends at its own timeout,
 * a write within {@value #WRITE_TIMEOUT_MS} ms): jSerialComm's native code crashes the whole JVM when a port is
 * closed under a read. Calls that start after {@link #close} fail with {@link LinkClosedException}.
 */
public final class JSerialCommLink implements SerialLink {

    private static final int WRITE_TIMEOUT_MS = 2_000;
    /** Read timeouts below this are waited out by polling: jSerialComm's own are 100 ms coarse on Linux. */
    private static final long COARSE_TIMEOUT_MS = 100;
    private static final long POLL_PAUSE_NANOS = 200_000;
    /** How long a close waits for the calls under way; a call still in the port after that closes it when it ends. */
    private static final long CLOSE_WAIT_NANOS = 5_000_000_000L;

    private final String path;
    private final SerialSettings settings;
    private SerialPort port;
    private PortLock portLock;
    private volatile boolean open;
    private int currentReadTimeoutMs = -1;
    /** Guarded by this: calls now inside the port's native code. */
    private int callsInPort;
    /** Guarded by this: closed while a call was still inside the port; the last one to leave closes it. */
    private boolean closeWhenIdle;

    /** A link to {@code path}, not yet opened. */
    public JSerialCommLink(String path, SerialSettings settings) {
        this.path = path;
        this.settings = settings;
    }

    @Override
    public String portName() {
        return path;
    }

    @Override
    public synchronized void open() throws IOException {
        if (open) {
            return;
        }
        if (closeWhenIdle) {
            throw new IOException(path + ": cannot open the link again yet: a call of its last opening is still in"
                    + " the port");
        }
        PortLock lock = PortLock.acquire(path); // refuses a port another program holds, naming it
        SerialPort candidate;
        try {
            // resolves the path now: a pty link must already exist
            candidate = SerialPort.getCommPort(path);
        } catch (RuntimeException e) {
            lock.close();
            throw new IOException(path + ": no such serial port (" + e.getMessage() + ")", e);
        }
        candidate.setComPortParameters(settings.baudRate(), settings.dataBits(), stopBits(), parity());
        candidate.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
        candidate.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING | SerialPort.TIMEOUT_WRITE_BLOCKING,
                1, WRITE_TIMEOUT_MS);
        if (!candidate.openPort()) {
            lock.close();
            throw new IOException(path + ": cannot open serial port: " + reason(candidate.getLastErrorCode())
                    + " (error " + candidate.getLastErrorCode() + " at " + candidate.getLastErrorLocation() + ")");
        }
        portLock = lock;
        port = candidate;
        currentReadTimeoutMs = 1;
        open = true;
    }

    @Override
    public boolean isOpen() {
        return open;
    }

    @Override
    public void write(byte[] bytes) throws IOException {
        SerialPort p = enter();
        try {
            int written = 0;
            while (written < bytes.length) {
                int n = p.writeBytes(bytes, bytes.length - written, written);
                if (n < 0) {
                    throw new LinkClosedException(path, "write failed: the device is gone");
                }
                if (n == 0) {
                    throw new IOException(path + ": write timed out after " + WRITE_TIMEOUT_MS + " ms");
                }
                written += n;
            }
        } finally {
            leave();
        }
    }

    @Override
    public int read(byte[] buffer, int offset, int length, Duration timeout) throws IOException {
        long millis = Math.max(0, Math.min(Integer.MAX_VALUE, timeout.toMillis()));
        if (millis == 0) {
            // jSerialComm reads "0 ms semi-blocking" as "wait forever": look instead
            int ready = available();
            if (ready == 0) {
                return 0;
            }
            length = Math.min(length, ready);
        } else if (millis < COARSE_TIMEOUT_MS) {
            // on Linux the read timeout is VTIME, in tenths of a second: a 10 ms wait would take 100 ms
            int ready = awaitAvailable(millis);
            if (ready == 0) {
                return 0;
            }
            length = Math.min(length, ready);
        }
        SerialPort p = enter();
        try {
            if (millis >= COARSE_TIMEOUT_MS) {
                setReadTimeout(p, (int) millis);
            }
            int n = p.readBytes(buffer, length, offset);
            if (n < 0) {
                throw new LinkClosedException(path, open ? "the device is gone" : "the link was closed");
            }
            return n;
        } finally {
            leave();
        }
    }

    /** Polls for data for up to {@code millis}; returns how many bytes are ready (0 when none came). */
    private int awaitAvailable(long millis) throws IOException {
        long deadline = System.nanoTime() + millis * 1_000_000;
        while (true) {
            int ready = available();
            long left = deadline - System.nanoTime();
            if (ready > 0 || left <= 0) {
                return ready;
            }
            LockSupport.parkNanos(Math.min(left, POLL_PAUSE_NANOS));
        }
    }

    @Override
    public int available() throws IOException {
        SerialPort p = enter();
        try {
            int n = p.bytesAvailable();
            if (n < 0) {
                throw new LinkClosedException(path, "the device is gone");
            }
            return n;
        } finally {
            leave();
        }
    }

    @Override
    public synchronized void close() {
        if (!open) {
            return;
        }
        open = false;
        long deadline = System.nanoTime() + CLOSE_WAIT_NANOS;
        boolean interrupted = false;
        while (callsInPort > 0) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                closeWhenIdle = true; // never under a call: the last one to leave closes the port
                return;
            }
            try {
                wait(left / 1_000_000 + 1);
            } catch (InterruptedException e) {
                interrupted = true; // closing is not optional; the interrupt is kept for the caller
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        closePort();
    }

    /** A call into the port begins; fails once the link is closed. */
    private synchronized SerialPort enter() throws IOException {
        if (!open) {
            throw new LinkClosedException(path, port == null ? "the link is not open" : "the link was closed");
        }
        callsInPort++;
        return port;
    }

    /** A call into the port has ended. */
    private synchronized void leave() {
        callsInPort--;
        if (callsInPort == 0) {
            if (closeWhenIdle) {
                closeWhenIdle = false;
                closePort();
            }
            notifyAll(); // a close waiting for this call
        }
    }

    private void closePort() {
        port.closePort();
        portLock.close();
    }

    /** What an operating system error of opening means, and what to do about it. */
    private static String reason(int errno) {
        return switch (errno) {
            case 2 -> "no such device";
            case 13 -> "permission denied (on Linux, join the group that owns it, e.g. 'sudo usermod -aG dialout "
                    + "$USER', then log in again)";
            case 16 -> "the device is busy: another program has it open";
            case 20, 21 -> "not a serial device";
            default -> "the operating system refused it";
        };
    }

    private void setReadTimeout(SerialPort p, int millis) {
        // only touch the port when the timeout changes: each change is a system call
        if (millis != currentReadTimeoutMs) {
            p.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING | SerialPort.TIMEOUT_WRITE_BLOCKING,
                    millis, WRITE_TIMEOUT_MS);
            currentReadTimeoutMs = millis;
        }
    }

    private int parity() {
        return switch (settings.parity()) {
            case NONE -> SerialPort.NO_PARITY;
            case ODD -> SerialPort.ODD_PARITY;
            case EVEN -> SerialPort.EVEN_PARITY;
            case MARK -> SerialPort.MARK_PARITY;
            case SPACE -> SerialPort.SPACE_PARITY;
        };
    }

    private int stopBits() {
        return switch (settings.stopBits()) {
            case ONE -> SerialPort.ONE_STOP_BIT;
            case ONE_POINT_FIVE -> SerialPort.ONE_POINT_FIVE_STOP_BITS;
            case TWO -> SerialPort.TWO_STOP_BITS;
        };
    }

    @Override
    public String toString() {
        return "serial " + path + " (" + settings + ")";
    }
}
