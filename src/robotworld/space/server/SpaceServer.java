package robotworld.space.server;

import java.io.IOException;
import java.net.InetAddress;
import java.net.URI;
import java.net.UnknownHostException;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.eclipse.jetty.ee10.servlet.ServletContextHandler;
import org.eclipse.jetty.ee10.servlet.ServletHolder;
import org.eclipse.jetty.server.HttpConfiguration;
import org.eclipse.jetty.server.HttpConnectionFactory;
import org.eclipse.jetty.server.NetworkConnectionLimit;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.handler.EagerContentHandler;
import org.eclipse.jetty.util.thread.QueuedThreadPool;
import robotworld.core.HostNames;
import robotworld.space.EmbeddedSpace;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.wire.CrefMapping;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireLimits;

/**
 * Serves a space over HTTP with an embedded Jetty: start it inside any JVM, hand its {@link #uri()} to the
 * participants (they open it with {@code RemoteSpace.open(uri)}), stop it when done.
 *
 * <pre>{@code
 * try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0))) {
 *     Capi space = RemoteSpace.open(server.uri());
 *     ...
 * }
 * }</pre>
 *
 * <p>The server is only the network front of its {@link EmbeddedSpace}: the entries live in the space, and so do
 * the takes waiting for their client's confirmation. Stopping the server (gracefully) answers waiting calls with
 * "stopping, no effect" and parks the notification sessions with the space; a new server started on the same port in front of the same space adopts them, and the clients
 * carry on without losing a notification. See {@code docs/wire.md}.
 */
public final class SpaceServer implements AutoCloseable {

    /** Threads for requests being worked on at once (waiting ones hold none), besides the notification streams. */
    private static final int MAX_BUSY_THREADS = 200;

    private final Server jetty;
    private final ClosingConnector connector;
    private final ServerState state;
    private final boolean ownsSpace;
    private final ScheduledExecutorService sessionTimer;
    private final int port;
    private boolean stopped;

    private SpaceServer(Server jetty, ClosingConnector connector, ServerState state, boolean ownsSpace,
                        ScheduledExecutorService sessionTimer, int port) {
        this.jetty = jetty;
        this.connector = connector;
        this.state = state;
        this.ownsSpace = ownsSpace;
        this.sessionTimer = sessionTimer;
        this.port = port;
    }

    /** Starts a server with a new, empty space whose crefs carry the server's URI; stopping closes the space. */
    public static SpaceServer start(Options options) {
        return start(null, options);
    }

    /**
     * Starts a server in front of an existing space, which stays open when the server stops (so a server can be
     * restarted in front of it). Crefs of the space are translated to the server's URI on the wire.
     */
    public static SpaceServer start(SpaceEngine space, Options options) {
        if (options.token() != null) {
            new BearerToken(options.token()); // reject an unusable token before binding anything
        }
        // waiting calls hold no thread: the threads run requests that are being worked on, plus one per
        // notification stream
        QueuedThreadPool threads = new QueuedThreadPool(options.maxSessions() + MAX_BUSY_THREADS, 4);
        threads.setName("space-server");
        threads.setIdleTimeout(10_000); // threads started for a burst of work end soon after it,
        threads.setMaxEvictCount(64);   // all of them, not one per idle timeout
        threads.setDaemon(true);
        Server jetty = new Server(threads);
        HttpConfiguration http = new HttpConfiguration();
        http.setSendServerVersion(false);
        http.setSendDateHeader(false);
        http.setOutputBufferSize(32 * 1024);
        http.setRequestHeaderSize(16 * 1024); // room for a batch of take confirmations (Space-Ack)
        // operations run on the selector threads (they never block): one selector per CPU, up to two
        int selectors = Math.min(2, Runtime.getRuntime().availableProcessors());
        boolean ownsSpace = space == null;
        // a connection answered from another thread reads on, on that thread, when the engine never blocks
        Executor connections = ownsSpace || !space.callsMayBlock() ? new ResumeInPlace(threads) : threads;
        // operation requests come as HTTP or, on connections upgraded to it, as frames
        FrameProtocol frames = new FrameProtocol();
        ClosingConnector connector = new ClosingConnector(jetty, connections, selectors,
                new HttpConnectionFactory(http), frames);
        connector.setHost(options.bindAddress());
        connector.setPort(options.port());
        connector.setAcceptQueueSize(1024); // a provider starting a thousand modules connects all at once
        connector.setIdleTimeout(Math.max(options.maxWaitMillis(), options.heartbeatMillis()) + 30_000);
        ClientLimits clients = new ClientLimits(options);
        connector.addBean(clients); // told of every connection opened and closed
        jetty.addConnector(connector);
        try {
            connector.open(); // bind now: the URI (and a space's crefs) need the actual port
        } catch (IOException e) {
            throw new SpaceException("cannot listen on " + options.bindAddress() + ":" + options.port() + ": "
                    + e.getMessage(), e);
        }
        int port = connector.getLocalPort();
        URI publicUri = options.publicUri() != null ? options.publicUri()
                : URI.create("http://" + uriHost(options.bindAddress()) + ":" + port + options.path());
        SpaceEngine served = ownsSpace ? EmbeddedSpace.open(publicUri, options.notificationQueue()) : space;
        // crefs carry the server's URL, unless the space has one URI on every server in front of it (a cluster)
        URI crefUri = served.sharedUri() ? served.spaceUri() : publicUri;
        WireContext wire = WireContext.of(options.limits(), CrefMapping.between(served.spaceUri(), crefUri));
        ServerState state = new ServerState(served, publicUri, wire, options, clients);
        frames.serve(state);
        if (!ownsSpace) {
            state.sessions.adopt(ParkedSessions.adopt(served)); // left by a server that stopped gracefully
        }

        ServletContextHandler context = new ServletContextHandler();
        context.setContextPath("/");
        context.addServlet(new ServletHolder("space", new SpaceServlet(state)), options.path() + "/*");
        context.setErrorHandler(new JsonErrorHandler(wire));
        // a request's body is read without holding a thread, and the servlet runs once it is all there: clients
        // that send slowly (a bad link, or on purpose) cannot take the threads that others' calls need
        jetty.setHandler(new EagerContentHandler(new OperationsHandler(state, context),
                new EagerContentHandler.RetainedContentLoaderFactory(options.limits().maxBodyBytes() + 1L, -1, false)));
        jetty.setErrorHandler(new JsonErrorHandler(wire));
        jetty.addBean(new NetworkConnectionLimit(options.maxConnections(), connector));
        jetty.setStopTimeout(options.stopGraceMillis());
        ScheduledExecutorService sessionTimer = Executors.newSingleThreadScheduledExecutor(task -> {
            Thread thread = new Thread(task, "space-server-sessions");
            thread.setDaemon(true);
            return thread;
        });
        long sessionGrace = TimeUnit.MILLISECONDS.toNanos(options.sessionGraceMillis());
        sessionTimer.scheduleWithFixedDelay(() -> state.sessions.expire(sessionGrace), 100, 100, TimeUnit.MILLISECONDS);
        sessionTimer.scheduleWithFixedDelay(clients::sweep, clients.sweepMillis(), clients.sweepMillis(),
                TimeUnit.MILLISECONDS);
        try {
            jetty.start();
        } catch (Exception e) {
            sessionTimer.shutdownNow();
            try {
                jetty.stop();
            } catch (Exception ignored) {
                // already failing
            }
            if (ownsSpace) {
                served.close();
            }
            throw new SpaceException("cannot start the space server: " + e.getMessage(), e);
        }
        return new SpaceServer(jetty, connector, state, ownsSpace, sessionTimer, port);
    }

    private static String uriHost(String bind) {
        String host = bind;
        if (bind.equals("0.0.0.0") || bind.equals("::") || bind.isEmpty()) {
            try {
                host = InetAddress.getLocalHost().getCanonicalHostName();
            } catch (UnknownHostException e) {
                host = HostNames.thisComputer(); // the kernel's name: others may resolve it even if we cannot
            }
        }
        return host.contains(":") ? "[" + host + "]" : host;
    }

    /** The kinds of the connections open now (Jetty's class names: HTTP, frames, detection), for tests. */
    java.util.List<String> connectionKinds() {
        java.util.List<String> kinds = new java.util.ArrayList<>();
        for (org.eclipse.jetty.server.Connector connector : jetty.getConnectors()) {
            for (org.eclipse.jetty.io.EndPoint endPoint : connector.getConnectedEndPoints()) {
                org.eclipse.jetty.io.Connection connection = endPoint.getConnection();
                kinds.add(connection == null ? "none" : connection.getClass().getSimpleName());
            }
        }
        return kinds;
    }

    /** The URL clients open, e.g. {@code http://127.0.0.1:9876/space}; also the space URI in crefs on the wire. */
    public URI uri() {
        return state.publicUri;
    }

    /** The port the server listens on (useful after asking for port 0). */
    public int port() {
        return port;
    }

    /** The space this server exposes. */
    public SpaceEngine space() {
        return state.space;
    }

    /** Unconfirmed takes currently held by the server (for monitoring and tests). */
    public int pendingAcknowledgements() {
        return state.receipts.held();
    }

    /**
     * Stops gracefully: waiting calls end with "stopping" (no effect, clients retry) and the notification sessions
     * are parked with the space for {@link Options#sessionGraceMillis()}. Takes not yet confirmed stay with the
     * space: a successor accepts their confirmations, or their entries come back when the lease runs out.
     * Idempotent.
     */
    public synchronized void stop() {
        if (stopped) {
            return;
        }
        stopped = true;
        state.stopping = true;
        long grace = TimeUnit.MILLISECONDS.toNanos(state.options.stopGraceMillis());
        long deadline = System.nanoTime() + grace;
        state.calls.cancelAll();
        try {
            state.calls.awaitIdle(grace);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        // unconfirmed takes stay with the space: a successor accepts their confirmations, or they come back
        parkSessions(deadline);
        shutDown();
    }

    /**
     * Stops abruptly, as a crash would: no grace, and the notification sessions are lost (clients re-subscribe).
     * Waiting calls are still undone, since the space outlives this server. For tests of client recovery.
     */
    public synchronized void kill() {
        if (stopped) {
            return;
        }
        stopped = true;
        state.stopping = true;
        state.sessions.releaseAll().forEach(SessionRegistry::closeQuietly);
        state.calls.cancelAll();
        jetty.setStopTimeout(0);
        shutDown();
    }

    /**
     * Ends the streams (their queued frames stay queued) and parks the sessions with the space, so that a server
     * started in front of it lets the clients resume; a space this server owns closes instead.
     */
    private void parkSessions(long deadline) {
        for (EventSession session : state.sessions.all()) {
            session.endStream();
        }
        try {
            while (state.sessions.all().stream().anyMatch(EventSession::hasStream) && System.nanoTime() < deadline) {
                Thread.sleep(2);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        List<EventSession> sessions = state.sessions.releaseAll();
        if (ownsSpace) {
            sessions.forEach(SessionRegistry::closeQuietly);
        } else {
            ParkedSessions.park(state.space, sessions, state.options.sessionGraceMillis());
        }
    }

    private void shutDown() {
        try {
            jetty.stop();
        } catch (Exception e) {
            System.getLogger(SpaceServer.class.getName()).log(System.Logger.Level.WARNING, "jetty stop failed", e);
        }
        connector.closeLeftOpen(); // those accepted while stopping, which Jetty may leave open and unserved
        state.calls.cancelAll();
        sessionTimer.shutdownNow();
        if (ownsSpace) {
            state.space.close();
        }
    }

    /** Same as {@link #stop()}. */
    @Override
    public void close() {
        stop();
    }

    @Override
    public String toString() {
        return "SpaceServer[" + state.publicUri + "]";
    }

    /**
     * How a server runs. Start from {@link #defaults()} and change what you need, e.g.
     * {@code Options.defaults().port(0).token(secret)}.
     *
     * @param bindAddress                address to listen on; loopback by default, so nothing outside the host reaches it
     * @param port                       TCP port; 0 picks a free one
     * @param path                       URL path of the space, e.g. {@code /space}
     * @param token                      bearer token every request must carry, or null for none
     * @param publicUri                  the URI clients use and crefs carry; null derives it from address, port and path
     * @param limits                     message size limits
     * @param maxWaitMillis              longest wait of one request inside the space; longer timeouts are split
     * @param leaseMillis                how long an unconfirmed take is held before its entries are put back
     * @param heartbeatMillis            notification streams carry a heartbeat at least this often
     * @param stopGraceMillis            how long a graceful stop waits for confirmations and streams
     * @param maxWaitingCalls            most requests waiting inside the space at once (then 503)
     * @param maxSessions                most notification streams at once
     * @param sessionQueue               notification frames queued per stream before its subscriptions overflow
     * @param maxSubscriptionsPerSession most subscriptions on one stream
     * @param notificationQueue          per-subscription queue of a space the server creates itself
     * @param sessionGraceMillis         how long a notification session waits for its client to reconnect (also
     *                                   across a graceful restart) before its subscriptions are cancelled
     * @param maxConnections             most open connections at once; at the limit the server stops accepting
     *                                   (new connections wait in the listen queue until one closes)
     * @param maxConnectionsPerClient    most open connections from one remote address; a connection beyond it has
     *                                   its first request answered 503 {@code busy} and is closed, unless that
     *                                   request carries the token
     * @param maxWaitingPerClient        most operations waiting at once from one remote address (then, like at
     *                                   {@code maxWaitingCalls}, only an operation that would have to wait gets
     *                                   503 {@code busy}); requests that carry the token are not counted
     * @param requestReadMillis          how long a request's head and body may take to arrive, from its first
     *                                   byte; a connection still sending one then is closed, at most
     *                                   {@code min(2 s, requestReadMillis / 2)} later (idle connections and
     *                                   waiting requests are not affected)
     */
    public record Options(String bindAddress, int port, String path, String token, URI publicUri, WireLimits limits,
                          long maxWaitMillis, long leaseMillis, long heartbeatMillis, long stopGraceMillis,
                          int maxWaitingCalls, int maxSessions, int sessionQueue, int maxSubscriptionsPerSession,
                          int notificationQueue, long sessionGraceMillis, int maxConnections,
                          int maxConnectionsPerClient, int maxWaitingPerClient, long requestReadMillis) {

        /** The port used when none is given. */
        public static final int DEFAULT_PORT = 9876;

        /** Connections, and waiting operations, one remote address may hold by default: half the server's. */
        public static final int DEFAULT_PER_CLIENT = 2_048;

        /** How long a request may take to arrive by default. */
        public static final long DEFAULT_REQUEST_READ_MILLIS = 10_000;

        /** Validates the values. */
        public Options {
            if (port < 0 || port > 65_535) {
                throw new IllegalArgumentException("port must be 0..65535; was " + port);
            }
            if (!path.startsWith("/") || path.endsWith("/") || path.contains("*")) {
                throw new IllegalArgumentException("path must start with '/', not end with one, no '*': " + path);
            }
            if (maxWaitMillis < 10 || leaseMillis < 10 || heartbeatMillis < 10 || stopGraceMillis < 0
                    || maxWaitingCalls < 1 || maxSessions < 1 || sessionQueue < 1 || maxSubscriptionsPerSession < 1
                    || notificationQueue < 1 || sessionGraceMillis < 10 || maxConnections < 1
                    || maxConnectionsPerClient < 1 || maxWaitingPerClient < 1 || requestReadMillis < 10) {
                throw new IllegalArgumentException("server times and limits must be positive");
            }
        }

        /**
         * Loopback, port 9876, path {@code /space}, no token, default limits, 20 s waits, 10 s leases; 4 096
         * connections and 4 096 waiting operations, at most half of each from one address; 10 s for a request to
         * arrive.
         */
        public static Options defaults() {
            return new Options("127.0.0.1", DEFAULT_PORT, "/space", null, null, WireLimits.DEFAULTS, 20_000, 10_000,
                    2_000, 1_000, 4_096, 128, 10_000, 1_000, EmbeddedSpace.DEFAULT_NOTIFICATION_QUEUE, 10_000, 4_096,
                    DEFAULT_PER_CLIENT, DEFAULT_PER_CLIENT, DEFAULT_REQUEST_READ_MILLIS);
        }

        /** With another address to listen on. */
        public Options bindAddress(String address) {
            return new Options(address, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, sessionGraceMillis, maxConnections,
                    maxConnectionsPerClient, maxWaitingPerClient, requestReadMillis);
        }

        /** With another port (0: any free one). */
        public Options port(int newPort) {
            return new Options(bindAddress, newPort, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, sessionGraceMillis, maxConnections,
                    maxConnectionsPerClient, maxWaitingPerClient, requestReadMillis);
        }

        /** With a bearer token every request must carry. */
        public Options token(String newToken) {
            return new Options(bindAddress, port, path, newToken, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, sessionGraceMillis, maxConnections,
                    maxConnectionsPerClient, maxWaitingPerClient, requestReadMillis);
        }

        /** With the URI clients use and crefs carry. */
        public Options publicUri(URI uri) {
            return new Options(bindAddress, port, path, token, uri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, sessionGraceMillis, maxConnections,
                    maxConnectionsPerClient, maxWaitingPerClient, requestReadMillis);
        }

        /** With other message limits. */
        public Options limits(WireLimits newLimits) {
            return new Options(bindAddress, port, path, token, publicUri, newLimits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, sessionGraceMillis, maxConnections,
                    maxConnectionsPerClient, maxWaitingPerClient, requestReadMillis);
        }

        /** With another longest wait per request. */
        public Options maxWaitMillis(long millis) {
            return new Options(bindAddress, port, path, token, publicUri, limits, millis, leaseMillis, heartbeatMillis,
                    stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue, maxSubscriptionsPerSession,
                    notificationQueue, sessionGraceMillis, maxConnections, maxConnectionsPerClient,
                    maxWaitingPerClient, requestReadMillis);
        }

        /** With another lease for unconfirmed takes. */
        public Options leaseMillis(long millis) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, millis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, sessionGraceMillis, maxConnections,
                    maxConnectionsPerClient, maxWaitingPerClient, requestReadMillis);
        }

        /** With another heartbeat period. */
        public Options heartbeatMillis(long millis) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis, millis,
                    stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue, maxSubscriptionsPerSession,
                    notificationQueue, sessionGraceMillis, maxConnections, maxConnectionsPerClient,
                    maxWaitingPerClient, requestReadMillis);
        }

        /** With another grace period for a graceful stop. */
        public Options stopGraceMillis(long millis) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, millis, maxWaitingCalls, maxSessions, sessionQueue, maxSubscriptionsPerSession,
                    notificationQueue, sessionGraceMillis, maxConnections, maxConnectionsPerClient,
                    maxWaitingPerClient, requestReadMillis);
        }

        /** With another bound on waiting requests. */
        public Options maxWaitingCalls(int calls) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, calls, maxSessions, sessionQueue, maxSubscriptionsPerSession,
                    notificationQueue, sessionGraceMillis, maxConnections, maxConnectionsPerClient,
                    maxWaitingPerClient, requestReadMillis);
        }

        /** With another grace period for reconnecting notification sessions. */
        public Options sessionGraceMillis(long millis) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, millis, maxConnections, maxConnectionsPerClient,
                    maxWaitingPerClient, requestReadMillis);
        }

        /** With another bound on open connections (then new ones wait in the listen queue). */
        public Options maxConnections(int connections) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, notificationQueue, sessionGraceMillis, connections,
                    maxConnectionsPerClient, maxWaitingPerClient, requestReadMillis);
        }

        /** With another bound on open connections from one remote address. */
        public Options maxConnectionsPerClient(int connections) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue, maxSubscriptionsPerSession,
                    notificationQueue, sessionGraceMillis, maxConnections, connections, maxWaitingPerClient, requestReadMillis);
        }

        /** With another bound on waiting operations from one remote address. */
        public Options maxWaitingPerClient(int calls) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue, maxSubscriptionsPerSession,
                    notificationQueue, sessionGraceMillis, maxConnections, maxConnectionsPerClient, calls, requestReadMillis);
        }

        /** With another deadline for a request's head and body to arrive. */
        public Options requestReadMillis(long millis) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue, maxSubscriptionsPerSession,
                    notificationQueue, sessionGraceMillis, maxConnections, maxConnectionsPerClient, maxWaitingPerClient, millis);
        }

        /** With another per-subscription queue for a space the server creates. */
        public Options notificationQueue(int capacity) {
            return new Options(bindAddress, port, path, token, publicUri, limits, maxWaitMillis, leaseMillis,
                    heartbeatMillis, stopGraceMillis, maxWaitingCalls, maxSessions, sessionQueue,
                    maxSubscriptionsPerSession, capacity, sessionGraceMillis, maxConnections, maxConnectionsPerClient,
                    maxWaitingPerClient, requestReadMillis);
        }
    }
}
