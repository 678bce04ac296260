package robotworld.testsupport;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A TCP forwarder in front of a server that can make the server <em>unreachable</em>, the way a crashed host or a
 * network that drops packets does, rather than refusing: in {@link #blackhole()} it stops accepting and fills its
 * accept queue (backlog 1), so new connections never complete and time out; open connections stay open but
 * silent in both directions. {@link #restore()} drops what was held and forwards again.
 */
public final class TcpBlackhole implements AutoCloseable {

    private final ServerSocket listener;
    private final InetSocketAddress target;
    private final Set<Socket> open = ConcurrentHashMap.newKeySet();
    private final List<Socket> fillers = new ArrayList<>();
    private final Thread acceptor;
    private volatile boolean silent;
    private volatile boolean closed;

    public TcpBlackhole(String targetHost, int targetPort) throws IOException {
        this.target = new InetSocketAddress(targetHost, targetPort);
        this.listener = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        this.acceptor = new Thread(this::accept, "blackhole-accept");
        acceptor.setDaemon(true);
        acceptor.start();
    }

    /** The port clients connect to. */
    public int port() {
        return listener.getLocalPort();
    }

    /** From now on: no new connection completes, open ones carry nothing. */
    public synchronized void blackhole() throws IOException {
        silent = true;
        // the acceptor no longer accepts: two connections fill the queue of a backlog-1 listener, and the kernel
        // then drops further connection attempts (they retry until their connect timeout)
        for (int i = 0; i < 3; i++) {
            Socket filler = new Socket();
            try {
                filler.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port()), 300);
                fillers.add(filler);
            } catch (IOException full) {
                filler.close();
                break; // the queue is already full
            }
        }
    }

    /** Back to forwarding; what was held is dropped, as after a host came back. */
    public synchronized void restore() throws IOException {
        for (Socket socket : open) {
            socket.close();
        }
        open.clear();
        for (Socket filler : fillers) {
            filler.close();
        }
        fillers.clear();
        silent = false;
        synchronized (this) {
            notifyAll();
        }
    }

    private void accept() {
        while (!closed) {
            synchronized (this) {
                while (silent && !closed) {
                    try {
                        wait(50);
                    } catch (InterruptedException e) {
                        return;
                    }
                }
            }
            try {
                Socket client = listener.accept();
                if (silent) {
                    client.close();
                    continue;
                }
                Socket server = new Socket();
                server.connect(target, 2_000);
                open.add(client);
                open.add(server);
                pump(client, server);
                pump(server, client);
            } catch (IOException e) {
                if (closed) {
                    return;
                }
            }
        }
    }

    private void pump(Socket from, Socket to) {
        Thread thread = new Thread(() -> {
            byte[] buffer = new byte[8192];
            try (InputStream in = from.getInputStream(); OutputStream out = to.getOutputStream()) {
                int n;
                while ((n = in.read(buffer)) >= 0) {
                    if (!silent) { // silent: what arrives is swallowed, as by a host that has gone
                        out.write(buffer, 0, n);
                        out.flush();
                    }
                }
            } catch (IOException e) {
                // one side closed
            } finally {
                if (!silent) {
                    closeQuietly(from);
                    closeQuietly(to);
                }
            }
        }, "blackhole-pump");
        thread.setDaemon(true);
        thread.start();
    }

    private static void closeQuietly(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            // already closed
        }
    }

    @Override
    public void close() throws IOException {
        closed = true;
        restore();
        listener.close();
    }
}
