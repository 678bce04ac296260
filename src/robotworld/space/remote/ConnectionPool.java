package robotworld.space.remote;

import java.io.IOException;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.TimeUnit;

/**
 * Keep-alive connections to one server: a call borrows one (or opens a new one), and gives it back after a
 * complete exchange. Connections in use are tracked so that closing the client can break their waits.
 */
final class ConnectionPool {

    private final Endpoint endpoint;
    private final int connectTimeoutMillis;
    private final int maxIdle;
    private final ConcurrentLinkedDeque<HttpConnection> idle = new ConcurrentLinkedDeque<>();
    private final Set<HttpConnection> inUse = ConcurrentHashMap.newKeySet();
    private volatile boolean closed;
    /** Whether new connections carry operations as frames (the server said it takes them). */
    private volatile boolean framed;

    ConnectionPool(Endpoint endpoint, int connectTimeoutMillis, int maxIdle) {
        this.endpoint = endpoint;
        this.connectTimeoutMillis = connectTimeoutMillis;
        this.maxIdle = maxIdle;
    }

    /**
     * An idle connection, or a new one.
     *
     * @param deadline {@link System#nanoTime()} by which a new connection must be made: a server that does not
     *                 accept (host down, packets dropped, accept queue full) cannot hold the call past it
     * @throws java.net.SocketTimeoutException when the connection could not be made in time
     */
    HttpConnection borrow(long deadline) throws IOException {
        HttpConnection connection = idle.pollFirst(); // most recently used first: least likely to be stale
        if (connection == null) {
            connection = new HttpConnection(endpoint.host(), endpoint.port(), connectTimeout(deadline));
            if (framed) {
                upgrade(connection, deadline);
            }
        }
        return track(connection);
    }

    /** As {@link #borrow}, a connection for any HTTP request (an idle framed one is not). */
    HttpConnection borrowHttp(long deadline) throws IOException {
        HttpConnection connection = idle.pollFirst();
        if (connection != null && connection.framed) {
            idle.addFirst(connection);
            connection = null;
        }
        if (connection == null) {
            connection = new HttpConnection(endpoint.host(), endpoint.port(), connectTimeout(deadline));
        }
        return track(connection);
    }

    /** Whether new connections carry operations as frames. */
    boolean framed() {
        return framed;
    }

    /** The server did not switch a connection to frames: it is not asked again. */
    void noFrames() {
        framed = false;
    }

    /** From now on, new connections carry operations as frames (the idle HTTP ones are closed). */
    void useFrames() {
        framed = true;
        discardIdle();
    }

    /** Makes a new connection a framed one; a server that does not take frames is not asked again. */
    private void upgrade(HttpConnection connection, long deadline) throws IOException {
        try {
            if (!connection.upgradeToFrames(endpoint, deadline)) {
                framed = false;
            }
        } catch (IOException | RuntimeException e) {
            connection.close();
            throw e;
        }
    }

    private HttpConnection track(HttpConnection connection) throws IOException {
        inUse.add(connection);
        if (closed) {
            discard(connection);
            throw new IOException("the client is closed");
        }
        return connection;
    }

    /** Returns a connection after a complete exchange. */
    void release(HttpConnection connection) {
        inUse.remove(connection);
        if (!connection.isOpen() || closed || idle.size() >= maxIdle) {
            connection.close();
            return;
        }
        idle.addFirst(connection);
    }

    /** The connect timeout for a new connection: the configured one, cut to what is left before {@code deadline}. */
    int connectTimeout(long deadline) {
        long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
        return (int) Math.max(1, Math.min(connectTimeoutMillis, left)); // 0 would mean "no timeout" to a socket
    }

    /** Closes a connection after a failed exchange; nothing to do for a connection that was never made. */
    void discard(HttpConnection connection) {
        if (connection == null) {
            return;
        }
        inUse.remove(connection);
        connection.close();
    }

    /** Closes the idle connections: after the server went away they are all stale. */
    void discardIdle() {
        HttpConnection connection;
        while ((connection = idle.pollFirst()) != null) {
            connection.close();
        }
    }

    /** Closes everything, including connections in use, which breaks the waits of their calls. */
    void close() {
        closed = true;
        discardIdle();
        for (HttpConnection connection : inUse) {
            connection.close();
        }
    }
}
