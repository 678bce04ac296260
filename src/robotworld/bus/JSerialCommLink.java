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
 */
public final class JSerialCommLink implements SerialLink {

    private static final int WRITE_TIMEOUT_MS = 2_000;
    /** Read timeouts below this are waited out by polling: jSerialComm's own are 100 ms coarse on Linux. */
    private static final long COARSE_TIMEOUT_MS = 100;
    private static final long POLL_PAUSE_NANOS = 200_000;

    private final String path;
    private final SerialSettings settings;
    private SerialPort port;
    private PortLock portLock;
    private volatile boolean open;
    private int currentReadTimeoutMs = -1;

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
        SerialPort p = requireOpen();
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
    }

    @Override
    public int read(byte[] buffer, int offset, int length, Duration timeout) throws IOException {
        SerialPort p = requireOpen();
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
        } else {
            setReadTimeout((int) millis);
        }
        int n = p.readBytes(buffer, length, offset);
        if (n < 0) {
            throw new LinkClosedException(path, open ? "the device is gone" : "the link was closed");
        }
        return n;
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
        int n = requireOpen().bytesAvailable();
        if (n < 0) {
            throw new LinkClosedException(path, "the device is gone");
        }
        return n;
    }

    @Override
    public synchronized void close() {
        if (!open) {
            return;
        }
        open = false;
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

    private void setReadTimeout(int millis) {
        // only touch the port when the timeout changes: each change is a system call
        if (millis != currentReadTimeoutMs) {
            port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING | SerialPort.TIMEOUT_WRITE_BLOCKING,
                    millis, WRITE_TIMEOUT_MS);
            currentReadTimeoutMs = millis;
        }
    }

    private SerialPort requireOpen() throws IOException {
        if (!open) {
            throw new LinkClosedException(path, "the link is not open");
        }
        return port;
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
