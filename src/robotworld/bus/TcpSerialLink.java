package robotworld.bus;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.time.Duration;

/**
 * A {@link SerialLink} over a raw TCP byte stream, as offered by serial-over-TCP bridges (ser2net in raw mode)
 * and by this project's simulators. Serial line settings live at the bridge and are not sent.
 */
public final class TcpSerialLink implements SerialLink {

    /** How long {@link #open()} waits for the connection. */
    public static final Duration CONNECT_TIMEOUT = Duration.ofSeconds(5);

    private final String host;
    private final int port;
    private final String portName;
    private Socket socket;
    private InputStream in;
    private OutputStream out;
    private volatile boolean open;
    private int currentTimeoutMs = -1;

    /** A link that connects to {@code host:port} when opened. */
    public TcpSerialLink(String host, int port) {
        this.host = host;
        this.port = port;
        this.portName = new PortName.Tcp(host, port).text();
    }

    /** Wraps a socket that is already connected (e.g. one a simulator accepted); the link is open. */
    public TcpSerialLink(Socket connected) throws IOException {
        this.host = connected.getInetAddress().getHostAddress();
        this.port = connected.getPort();
        this.portName = new PortName.Tcp(host, port).text();
        attach(connected);
    }

    @Override
    public String portName() {
        return portName;
    }

    @Override
    public synchronized void open() throws IOException {
        if (open) {
            return;
        }
        Socket candidate = new Socket();
        try {
            candidate.connect(new InetSocketAddress(host, port), (int) CONNECT_TIMEOUT.toMillis());
        } catch (IOException e) {
            candidate.close();
            throw new IOException(portName + ": cannot connect (" + e.getMessage() + ")", e);
        }
        attach(candidate);
    }

    private void attach(Socket connected) throws IOException {
        connected.setTcpNoDelay(true); // a CM11A frame is two bytes: never hold them back
        currentTimeoutMs = -1; // a new socket (e.g. after close and open) has no read timeout yet
        socket = connected;
        in = connected.getInputStream();
        out = connected.getOutputStream();
        open = true;
    }

    @Override
    public boolean isOpen() {
        return open;
    }

    @Override
    public void write(byte[] bytes) throws IOException {
        requireOpen();
        try {
            out.write(bytes);
            out.flush();
        } catch (SocketException e) {
            throw new LinkClosedException(portName, "connection lost (" + e.getMessage() + ")");
        }
    }

    @Override
    public int read(byte[] buffer, int offset, int length, Duration timeout) throws IOException {
        requireOpen();
        long millis = Math.max(0, Math.min(Integer.MAX_VALUE, timeout.toMillis()));
        if (millis == 0) {
            // a socket timeout of 0 means "forever": look instead
            int ready = available();
            if (ready == 0) {
                return 0;
            }
            length = Math.min(length, ready);
            millis = 1;
        }
        try {
            if (millis != currentTimeoutMs) {
                socket.setSoTimeout((int) millis);
                currentTimeoutMs = (int) millis;
            }
            int n = in.read(buffer, offset, length);
            if (n < 0) {
                throw new LinkClosedException(portName, "the peer closed the connection");
            }
            return n;
        } catch (SocketTimeoutException e) {
            return 0;
        } catch (SocketException e) {
            throw new LinkClosedException(portName, open ? "connection lost (" + e.getMessage() + ")"
                    : "the link was closed");
        }
    }

    @Override
    public boolean silenceMayMeanADeadConnection() {
        return true;
    }

    @Override
    public int available() throws IOException {
        requireOpen();
        return in.available();
    }

    @Override
    public synchronized void close() throws IOException {
        if (!open) {
            return;
        }
        open = false;
        socket.close();
    }

    private void requireOpen() throws IOException {
        if (!open) {
            throw new LinkClosedException(portName, "the link is not open");
        }
    }

    @Override
    public String toString() {
        return "tcp link " + portName;
    }
}
