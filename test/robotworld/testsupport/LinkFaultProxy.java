package robotworld.testsupport;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A loopback TCP relay between a client and a device server (a simulator), whose port stays the same while the
 * link behind it fails the ways real links do:
 * <ul>
 * <li>{@link #drop()}: every connection is closed and new ones are closed at once (the bridge or device is gone);</li>
 * <li>{@link #silence()}: connections stay open but nothing passes either way, as when a bridge crashed or the
 *     network cut it off without anyone closing the connection; new connections are silent too;</li>
 * <li>{@link #restore()}: new connections are relayed again; connections silenced before stay dead, as a
 *     half-open connection does after the far end restarted.</li>
 * </ul>
 */
public final class LinkFaultProxy implements AutoCloseable {

    private enum Mode { RELAY, DROP, SILENT }

    private final ServerSocket server;
    private final List<Pipe> pipes = new CopyOnWriteArrayList<>();
    private volatile int targetPort;
    private volatile Mode mode = Mode.RELAY;

    /** Relays to 127.0.0.1:{@code targetPort}. */
    public LinkFaultProxy(int targetPort) throws IOException {
        this.targetPort = targetPort;
        server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        Thread acceptor = new Thread(this::accept, "link-fault-proxy :" + server.getLocalPort());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    /** The port name clients connect to, e.g. {@code tcp://127.0.0.1:40123}. */
    public String portName() {
        return "tcp://127.0.0.1:" + server.getLocalPort();
    }

    /** Relays new connections to another port (the device came back elsewhere). */
    public void retarget(int port) {
        targetPort = port;
    }

    /** Closes every connection and refuses new ones (accepted, then closed at once). */
    public synchronized void drop() {
        mode = Mode.DROP;
        pipes.forEach(Pipe::close);
    }

    /** Lets nothing through any connection, old or new, without closing any. */
    public synchronized void silence() {
        mode = Mode.SILENT;
        pipes.forEach(pipe -> pipe.silent = true);
    }

    /** Relays new connections again; connections silenced before stay silent. */
    public synchronized void restore() {
        mode = Mode.RELAY;
    }

    /**
     * Adds a connection that was being set up while the mode may have changed (connecting to the device takes a
     * moment): it meets the fault now in force, so that no connection escapes a {@link #drop()} or
     * {@link #silence()}.
     */
    private synchronized void register(Pipe pipe) throws IOException {
        if (mode == Mode.DROP) {
            pipe.close();
            return;
        }
        if (mode == Mode.SILENT) {
            pipe.silent = true;
        }
        pipes.add(pipe);
        pipe.start();
    }

    /** Keeps a copy of what clients send from now on, for {@link #clientBytes()} (off by default: soaks relay much). */
    public void captureClientBytes() {
        capturing = true;
    }

    /** What clients sent through the proxy since {@link #captureClientBytes()} (all connections, in arrival order per read). */
    public byte[] clientBytes() {
        synchronized (sent) {
            return sent.toByteArray();
        }
    }

    private final java.io.ByteArrayOutputStream sent = new java.io.ByteArrayOutputStream();
    private volatile boolean capturing;

    /** How many connections clients have made. */
    public int connections() {
        return accepted;
    }

    private volatile int accepted;

    private void accept() {
        while (!server.isClosed()) {
            try {
                Socket client = server.accept();
                accepted++;
                client.setTcpNoDelay(true);
                switch (mode) {
                    case DROP -> client.close();
                    case SILENT -> register(new Pipe(client, null, true));
                    case RELAY -> {
                        Socket device = new Socket();
                        try {
                            device.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), targetPort), 2_000);
                            device.setTcpNoDelay(true);
                            register(new Pipe(client, device, false));
                        } catch (IOException e) {
                            device.close();
                            client.close(); // nothing listens behind us: as if the bridge refused
                        }
                    }
                    default -> throw new IllegalStateException();
                }
            } catch (IOException e) {
                // closed, or one connection failed: go on
            }
        }
    }

    @Override
    public synchronized void close() throws IOException {
        server.close();
        pipes.forEach(Pipe::close);
    }

    /** One relayed connection: a thread per direction. */
    private final class Pipe {
        private final Socket client;
        private final Socket device;
        private volatile boolean silent;

        Pipe(Socket client, Socket device, boolean silent) {
            this.client = client;
            this.device = device;
            this.silent = silent;
        }

        void start() throws IOException {
            start(client, device, "up");
            if (device != null) {
                start(device, client, "down");
            }
        }

        private void start(Socket from, Socket to, String direction) throws IOException {
            InputStream in = from.getInputStream();
            OutputStream out = to == null ? null : to.getOutputStream();
            Thread thread = new Thread(() -> {
                byte[] buffer = new byte[4096];
                try {
                    int n;
                    while ((n = in.read(buffer)) >= 0) {
                        if (!silent && out != null) {
                            if (capturing && from == client) {
                                synchronized (sent) {
                                    sent.write(buffer, 0, n);
                                }
                            }
                            out.write(buffer, 0, n);
                            out.flush();
                        }
                    }
                } catch (IOException e) {
                    // closed
                }
                if (!silent) {
                    close();
                }
            }, "link-fault-proxy " + direction);
            thread.setDaemon(true);
            thread.start();
        }

        void close() {
            try {
                client.close();
                if (device != null) {
                    device.close();
                }
            } catch (IOException e) {
                // closing anyway
            }
            pipes.remove(this);
        }
    }
}
