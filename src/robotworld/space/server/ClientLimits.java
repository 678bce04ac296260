package robotworld.space.server;

import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.io.Connection;
import org.eclipse.jetty.server.Request;

/**
 * What one client may hold of a server, so that no client can starve the others: connections per remote address,
 * operations waiting in the space per remote address, and how long a request may take to arrive.
 *
 * <ul>
 *   <li>A connection beyond {@link SpaceServer.Options#maxConnectionsPerClient()} from its address is accepted but
 *   kept only for the request deadline, and its first request is answered {@code 503 busy} (naming the limit)
 *   and the connection closed, unless that request carries the server's token.</li>
 *   <li>An operation that would wait beyond {@link SpaceServer.Options#maxWaitingPerClient()} waiting operations
 *   of its address is treated as at the server's own limit: if it can complete at once it does, otherwise
 *   {@code 503 busy}. Requests that carry the server's token are not counted.</li>
 *   <li>A request's head and body must arrive within {@link SpaceServer.Options#requestReadMillis()} of its
 *   first byte, or its connection is closed: a client trickling a byte a second cannot keep it for long.</li>
 * </ul>
 *
 * Connections are seen through Jetty's connection events; a request's progress through the bytes its connection
 * has received (a sweep every {@link #sweepMillis()}), and its arrival when the handler gets it (after the body,
 * which an {@code EagerContentHandler} reads first).
 */
final class ClientLimits implements Connection.Listener {

    private static final System.Logger LOG = System.getLogger(ClientLimits.class.getName());

    private final int maxConnections;
    private final int maxWaiting;
    private final long readMillis;
    private final BearerToken token;
    private final Map<Connection, Tracked> connections = new ConcurrentHashMap<>();
    private final Map<InetAddress, Integer> connectionsByAddress = new ConcurrentHashMap<>();
    private final Map<InetAddress, Integer> waitingByAddress = new ConcurrentHashMap<>();

    ClientLimits(SpaceServer.Options options) {
        this.maxConnections = options.maxConnectionsPerClient();
        this.maxWaiting = options.maxWaitingPerClient();
        this.readMillis = options.requestReadMillis();
        this.token = options.token() == null ? null : new BearerToken(options.token());
    }

    /** How often connections are checked for a request that is overdue; the deadline is enforced this late at most twice. */
    long sweepMillis() {
        return Math.max(20, Math.min(1_000, readMillis / 4));
    }

    @Override
    public void onOpened(Connection connection) {
        InetAddress address = addressOf(connection.getEndPoint().getRemoteSocketAddress());
        int count = address == null ? 0 : connectionsByAddress.merge(address, 1, Integer::sum);
        boolean overCap = count > maxConnections;
        Tracked tracked = new Tracked(connection, address, overCap);
        connections.put(connection, tracked);
        if (overCap) {
            tracked.idleTimeout = connection.getEndPoint().getIdleTimeout();
            connection.getEndPoint().setIdleTimeout(Math.min(tracked.idleTimeout, readMillis));
        }
    }

    @Override
    public void onClosed(Connection connection) {
        Tracked tracked = connections.remove(connection);
        if (tracked != null && tracked.address != null) {
            connectionsByAddress.computeIfPresent(tracked.address, (a, n) -> n <= 1 ? null : n - 1);
        }
    }

    /**
     * A request has arrived whole on its connection (head and body). Returns why it is refused (a message naming
     * the limit), or null if it may go on.
     */
    String arrived(Request request) {
        return arrived(request.getConnectionMetaData().getConnection(), hasToken(request));
    }

    /** As {@link #arrived(Request)}, for a request on {@code connection}; {@code withToken}: it has the server's token. */
    String arrived(Connection connection, boolean withToken) {
        Tracked tracked = connections.get(connection);
        if (tracked == null) {
            return null;
        }
        synchronized (tracked) {
            tracked.bytesAtArrival = tracked.connection.getBytesIn();
            tracked.readingSince = 0;
            if (!tracked.overCap) {
                return null;
            }
            if (withToken) {
                tracked.overCap = false; // a client with the token is not limited per address
                tracked.connection.getEndPoint().setIdleTimeout(tracked.idleTimeout);
                return null;
            }
        }
        return "too many connections from " + tracked.address.getHostAddress() + ": a space server keeps at most "
                + maxConnections + " per address (maxConnectionsPerClient, rwe space --max-connections-per-client)";
    }

    /** The address whose waiting operations count against its limit: null for a request with the server's token. */
    InetAddress waitingClient(Request request) {
        return waitingClient(request.getConnectionMetaData().getRemoteSocketAddress(), hasToken(request));
    }

    /** As {@link #waitingClient(Request)}, for a request from {@code address}. */
    InetAddress waitingClient(SocketAddress address, boolean withToken) {
        return withToken ? null : addressOf(address);
    }

    /** Takes a waiting place of {@code client}'s address (null: not limited); false if it has none left. */
    boolean enterWaiting(InetAddress client) {
        if (client == null) {
            return true;
        }
        boolean[] entered = new boolean[1];
        waitingByAddress.compute(client, (a, n) -> {
            int now = n == null ? 0 : n;
            if (now >= maxWaiting) {
                return n;
            }
            entered[0] = true;
            return now + 1;
        });
        return entered[0];
    }

    /** Gives back a place taken with {@link #enterWaiting}. */
    void leaveWaiting(InetAddress client) {
        if (client != null) {
            waitingByAddress.computeIfPresent(client, (a, n) -> n <= 1 ? null : n - 1);
        }
    }

    /** Why an operation of {@code client} found no waiting place of its address. */
    String waitingRefusal(InetAddress client) {
        return "too many operations are waiting from " + client.getHostAddress() + ": a space server lets at most "
                + maxWaiting + " wait per address (maxWaitingPerClient, rwe space --max-waiting-per-client); try again";
    }

    /**
     * Closes the connections whose request has been arriving for longer than the deadline. A connection is
     * reading a request from the sweep that first sees bytes beyond those of its last request.
     */
    void sweep() {
        long now = System.nanoTime();
        long deadline = TimeUnit.MILLISECONDS.toNanos(readMillis);
        for (Tracked tracked : connections.values()) {
            boolean overdue;
            synchronized (tracked) {
                if (tracked.cut) {
                    continue;
                }
                if (tracked.readingSince == 0) {
                    if (tracked.connection.getBytesIn() > tracked.bytesAtArrival) {
                        tracked.readingSince = now;
                    }
                    continue;
                }
                overdue = now - tracked.readingSince > deadline;
                tracked.cut = overdue;
            }
            if (overdue) {
                LOG.log(Level.DEBUG, () -> "closing a connection from " + tracked.address
                        + ": its request did not arrive within " + readMillis + " ms");
                tracked.connection.close(); // forgotten when Jetty reports it closed
            }
        }
    }

    private boolean hasToken(Request request) {
        return token != null && token.accepts(request.getHeaders().get(HttpHeader.AUTHORIZATION));
    }

    private static InetAddress addressOf(SocketAddress address) {
        return address instanceof InetSocketAddress inet ? inet.getAddress() : null;
    }

    /** One open connection. */
    private static final class Tracked {
        final Connection connection;
        final InetAddress address;
        /** Guarded by this. */
        boolean overCap;
        long idleTimeout;
        /** Bytes the connection had received when its last request arrived whole; guarded by this. */
        long bytesAtArrival;
        /** Whether the sweep closed it; guarded by this. */
        boolean cut;
        /** When a sweep first saw bytes of the next request, or 0; guarded by this. */
        long readingSince;

        Tracked(Connection connection, InetAddress address, boolean overCap) {
            this.connection = connection;
            this.address = address;
            this.overCap = overCap;
        }
    }
}
