package robotworld.space.remote;

import java.io.IOException;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedDeque;

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

    ConnectionPool(Endpoint endpoint, int connectTimeoutMillis, int maxIdle) {
        this.endpoint = endpoint;
        this.connectTimeoutMillis = connectTimeoutMillis;
        this.maxIdle = maxIdle;
    }

    HttpConnection borrow() throws IOException {
        HttpConnection connection = idle.pollFirst(); // most recently used first: least likely to be stale
        if (connection == null) {
            connection = new HttpConnection(endpoint.host(), endpoint.port(), connectTimeoutMillis);
        }
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

    /** Closes a connection after a failed exchange. */
    void discard(HttpConnection connection) {
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
