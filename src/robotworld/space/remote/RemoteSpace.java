package robotworld.space.remote;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.net.URI;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import robotworld.space.AsyncTakes;
import robotworld.space.Capi;
import robotworld.space.ContainerInfo;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceRequestRejectedException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;
import robotworld.space.wire.BinaryWire;
import robotworld.space.wire.CrefMapping;
import robotworld.space.wire.Wire;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireError;
import robotworld.space.wire.WireFormatException;
import robotworld.space.wire.WireLimits;
import robotworld.space.wire.WireWriter;

/**
 * A space on a {@code SpaceServer}, reached over HTTP, with the same interface and semantics as the embedded
 * one.
 *
 * <pre>{@code
 * try (Capi space = RemoteSpace.open(URI.create("http://127.0.0.1:9876/space"))) {
 *     ContainerRef jobs = space.lookupOrCreateContainer(ContainerSpec.of(Order.FIFO).named("jobs"));
 *     space.write(jobs, Timeout.TRY_ONCE, Tuple.of("host-a", 42));
 * }
 * }</pre>
 *
 * <p><b>Waiting.</b> A call waits on the server at most the server's maximum per request; a longer timeout is
 * split into several requests, each read with a timeout a little longer than the server's wait. A call returns
 * or fails within its timeout plus {@link Options#networkAllowanceMillis()} (the allowance alone for calls that
 * do not wait), unless its timeout is infinite.
 *
 * <p><b>Failures</b> are the same exceptions as in-process, plus {@link SpaceUnavailableException} (naming the
 * server) when the server cannot be reached in time, and {@link SpaceRequestRejectedException} when it refuses
 * a request as such. Connection failures are retried until the call's deadline: a call that had no effect is
 * simply repeated, a take whose answer was lost is cancelled (the server puts its entries back) and repeated, a
 * write or shift whose answer was lost is asked about and repeated only if it did not happen.
 *
 * <p><b>Takes are confirmed.</b> The server keeps what a take (or destroy) removed until this client confirms it
 * received the answer; confirmations ride on the next request, or go alone within a millisecond. If the
 * confirmation never arrives, the server puts the entries back.
 *
 * <p><b>Interrupts.</b> Interrupting a thread that waits in a call cancels the call on the server; the call
 * throws {@link SpaceInterruptedException} and had no effect (or, for a write that happened just before the
 * cancel, returns normally with the interrupt flag set).
 *
 * <p><b>Notifications</b> arrive over one streaming HTTP response per client; if it breaks (server restart), the
 * client reconnects and re-establishes every subscription. A subscription that may have missed an operation in
 * between ends as {@link SubscriptionEnd#OVERFLOWED} instead of going on with a silent gap.
 */
public final class RemoteSpace implements Capi, AsyncTakes {

    private static final int BACKOFF_FIRST_MILLIS = 5;
    private static final int BACKOFF_MAX_MILLIS = 250;
    /** How often a client that left the first server of its list checks whether it can go back. */
    static final long HOME_CHECK_MILLIS = 2_000;
    /** The name a home check looks up: any name will do, found or not. */
    private static final String HOME_CHECK_NAME = "rwe-home-check";

    /** The servers of the space, in the order given; calls go to the current one and fail over to the next. */
    private final List<Endpoint> endpoints;
    /** Which server is current, and which failed lately (guarded by this). */
    private final ServerRotation rotation;
    private volatile Endpoint endpoint;
    final Options options;
    final WireContext wire;
    volatile ConnectionPool pool;
    private final AckQueue acks;
    private final ScheduledExecutorService timer;
    final ExecutorService delivery;
    final EventStream events; // package-private for tests
    /** Prefix of this client's call ids: 64 random bits, short enough to keep ack headers small. */
    private final String clientId = Long.toHexString(new java.security.SecureRandom().nextLong());
    private final AtomicLong lastCall = new AtomicLong();
    /** Waiting calls in progress, by call id, so that close() can cancel them on the server. */
    /** Calls that wait on the server, as settle references ({@link #settleRef}), for close() to cancel. */
    private final Map<String, Boolean> waitingCalls = new ConcurrentHashMap<>();
    /** A pool per server, in the order of {@link #endpoints}; calls in progress on a server left keep its pool. */
    private final List<ConnectionPool> pools;
    /** Whether a check that the first server answers again is under way. */
    private final AtomicBoolean checkingHome = new AtomicBoolean();
    private static final System.Logger LOG = System.getLogger(RemoteSpace.class.getName());
    /** Takes that wait without a thread; created when first used. */
    private AsyncCalls asyncCalls;
    private volatile URI spaceUri;
    volatile long serverMaxWaitMillis = 20_000;
    /** The server reads the binary form of the hot operations' bodies in frames, and this client may use it. */
    private volatile boolean binaryBodies;
    private volatile boolean closed;

    private RemoteSpace(List<URI> urls, Options options) {
        if (urls.isEmpty()) {
            throw new IllegalArgumentException("no space URL given");
        }
        List<Endpoint> all = new ArrayList<>();
        for (URI url : urls) {
            all.add(Endpoint.of(url, options.token()));
        }
        this.endpoints = List.copyOf(all);
        this.rotation = new ServerRotation(endpoints.size());
        this.endpoint = endpoints.get(0);
        this.options = options;
        this.wire = WireContext.of(new WireLimits(Integer.MAX_VALUE - 64, 256, Integer.MAX_VALUE - 64,
                Integer.MAX_VALUE, 1024, Integer.MAX_VALUE), CrefMapping.IDENTITY);
        List<ConnectionPool> perServer = new ArrayList<>();
        for (Endpoint server : endpoints) {
            perServer.add(new ConnectionPool(server, options.connectTimeoutMillis(), options.maxIdleConnections()));
        }
        this.pools = List.copyOf(perServer);
        this.pool = pools.get(0);
        ScheduledThreadPoolExecutor timerThread = new ScheduledThreadPoolExecutor(1, daemonThreads("space-client-timer"));
        // started now, not on its first task (which may come minutes later): a space's threads live exactly as
        // long as the space, so a program (or a test) that counts threads sees none appear after the fact
        timerThread.prestartCoreThread();
        this.timer = Executors.unconfigurableScheduledExecutorService(timerThread);
        this.delivery = Executors.newCachedThreadPool(daemonThreads("space-client-notify"));
        this.acks = new AckQueue(timer, options.ackDelayMicros(), this::sendAcks);
        this.events = new EventStream(this);
    }

    /** Connects to the space at {@code url} (e.g. {@code http://127.0.0.1:9876/space}) with default options. */
    public static RemoteSpace open(URI url) {
        return open(url, Options.defaults());
    }

    /**
     * Connects to the space at {@code url}: asks the server for its space URI and limits, retrying for up to
     * the network allowance.
     *
     * @throws SpaceUnavailableException     if the server cannot be reached in time
     * @throws SpaceRequestRejectedException if it refuses the client (e.g. 401 without the right token)
     */
    public static RemoteSpace open(URI url, Options options) {
        return open(List.of(url), options);
    }

    /**
     * Connects to a space served by several servers (the members of a cluster), trying them in the order given; a
     * call whose server fails goes on with the next one within its own timeout, settling what the failed server may
     * have done first (a take's entries go back, a write is not repeated if it happened). All servers must serve
     * the same space.
     *
     * @throws SpaceUnavailableException     if none of the servers can be reached in time
     * @throws SpaceRequestRejectedException if one refuses the client (e.g. 401 without the right token)
     */
    public static RemoteSpace open(List<URI> urls, Options options) {
        RemoteSpace space = new RemoteSpace(urls, options);
        try {
            space.hello();
        } catch (RuntimeException e) {
            space.close();
            throw e;
        }
        if (urls.size() > 1) {
            space.timer.scheduleWithFixedDelay(space::checkHome, HOME_CHECK_MILLIS, HOME_CHECK_MILLIS,
                    TimeUnit.MILLISECONDS);
        }
        return space;
    }

    /** The URL of the server this client talks to now. */
    public URI url() {
        return endpoint.url();
    }

    /** The URLs of all the servers this client may talk to, in the order given. */
    public List<URI> urls() {
        List<URI> urls = new ArrayList<>();
        for (Endpoint each : endpoints) {
            urls.add(each.url());
        }
        return urls;
    }

    /**
     * The server at {@code failed} could not be reached, or answered that it could not complete a call (or is
     * stopping), for the reason {@code why}: later calls go to the next server in the list that has not failed
     * lately ({@link ServerRotation}). Nothing changes if there is only one, or another call has already moved on.
     */
    void failover(Endpoint failed, Object why) {
        failover(failed, !(why instanceof ServerUnavailable || why instanceof String), why);
    }

    /** As {@link #failover(Endpoint, Object)}, saying whether the server could not be reached at all. */
    void failover(Endpoint failed, boolean couldNotBeReached, Object why) {
        if (endpoints.size() < 2 || closed) {
            return;
        }
        ConnectionPool old;
        ConnectionPool next;
        synchronized (this) {
            if (endpoint != failed) {
                return; // moved on already
            }
            int index = rotation.failed(System.nanoTime(), couldNotBeReached);
            endpoint = endpoints.get(index);
            old = pool;
            pool = pools.get(index);
            next = pool;
            if (asyncCalls != null) {
                asyncCalls.endpointChanged();
            }
        }
        old.discardIdle();
        next.discardIdle(); // left idle when this client last used that server: its idle timeout may have closed them
        LOG.log(System.Logger.Level.INFO, "space server " + failed.url() + (couldNotBeReached ? " does not answer ("
                : " cannot serve (") + (why instanceof Throwable t && t.getMessage() != null ? t.getMessage() : why)
                + "); going on with " + endpoint.url());
    }

    /**
     * A client that moved on from the first server of its list goes back to it once it serves again, so that
     * clients stay spread over the servers as their lists say (each list starting with a different server) instead
     * of piling up on the ones that never failed. Checked every {@link #HOME_CHECK_MILLIS}, once the first server's
     * failure is {@link ServerRotation#SUSPECT_NANOS} old, with a call that needs the space behind the server (a
     * cluster member that has not yet joined its cluster does not count); on a pool thread, since a silent server
     * costs a connect timeout. Calls in progress finish where they are.
     */
    private void checkHome() {
        Endpoint home = endpoints.get(0);
        synchronized (this) {
            if (closed || endpoint == home || !rotation.mayGoHome(System.nanoTime())) {
                return;
            }
        }
        if (!checkingHome.compareAndSet(false, true)) {
            return;
        }
        try {
            delivery.execute(() -> {
                try {
                    if (servesAgain(home)) {
                        goHome(home);
                    } else {
                        synchronized (this) {
                            rotation.homeFailed(System.nanoTime());
                        }
                    }
                } finally {
                    checkingHome.set(false);
                }
            });
        } catch (RejectedExecutionException closedMeanwhile) {
            checkingHome.set(false);
        }
    }

    /** Whether {@code server} answers a name lookup (found or not) within the network allowance. */
    private boolean servesAgain(Endpoint server) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis());
        byte[] request = encode((out, id, wait) -> out.field("name", HOME_CHECK_NAME), null, Timeout.TRY_ONCE);
        HttpConnection connection = null;
        try {
            connection = new HttpConnection(server.host(), server.port(), pool.connectTimeout(deadline));
            connection.sendOperation(server, "lookup", null, request, request.length);
            HttpConnection.Response response = connection.receive(deadline, () -> { });
            if (response.status() == 200) {
                return true;
            }
            Answer answer = parseAnswer(response);
            return answer.error != null && WireError.byKind(answer.error) == WireError.CONTAINER_NOT_FOUND;
        } catch (IOException | SpaceException e) {
            return false;
        } finally {
            if (connection != null) {
                connection.close();
            }
        }
    }

    private void goHome(Endpoint home) {
        Endpoint left;
        synchronized (this) {
            if (closed || endpoint == home) {
                return;
            }
            left = endpoint;
            endpoint = home;
            pool = pools.get(rotation.wentHome());
            pool.discardIdle(); // connections to the server before it failed
            if (asyncCalls != null) {
                asyncCalls.endpointChanged();
            }
        }
        pools.get(endpoints.indexOf(left)).discardIdle();
        LOG.log(System.Logger.Level.INFO, "space server " + home.url() + " serves again; going back to it from "
                + left.url());
    }

    @Override
    public URI spaceUri() {
        return spaceUri;
    }

    // ---- naming service ----

    @Override
    public ContainerRef createContainer(ContainerSpec spec) {
        Objects.requireNonNull(spec, "spec");
        return call("create", null, Retry.UNSAFE, (out, id, timeout) -> out.spec("spec", spec)).container;
    }

    @Override
    public ContainerRef lookupContainer(String name) {
        Objects.requireNonNull(name, "name");
        return call("lookup", null, Retry.IDEMPOTENT, (out, id, timeout) -> out.field("name", name)).container;
    }

    @Override
    public ContainerRef lookupOrCreateContainer(ContainerSpec spec) {
        Objects.requireNonNull(spec, "spec");
        if (spec.name() == null) {
            throw new IllegalArgumentException("lookup-or-create needs a named spec");
        }
        return call("lookupOrCreate", null, Retry.IDEMPOTENT, (out, id, timeout) -> out.spec("spec", spec)).container;
    }

    @Override
    public void destroyContainer(ContainerRef container) {
        Objects.requireNonNull(container, "container");
        call("destroyContainer", null, Retry.UNSAFE, (out, id, timeout) -> out.cref("container", container));
    }

    @Override
    public ContainerInfo describeContainer(ContainerRef container) {
        Objects.requireNonNull(container, "container");
        Answer answer = call("describe", null, Retry.IDEMPOTENT, (out, id, timeout) -> out.cref("container", container));
        return new ContainerInfo(answer.container, answer.spec, (int) answer.size, (int) answer.blocked,
                (int) answer.subscriptions);
    }

    // ---- operations ----

    @Override
    public List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors) {
        return retrieve("read", Retry.IDEMPOTENT, container, timeout, selectors).entries;
    }

    @Override
    public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
        return retrieve("take", Retry.REMOVAL, container, timeout, selectors).entries;
    }

    @Override
    public int destroy(ContainerRef container, Timeout timeout, Selector... selectors) {
        return (int) retrieve("destroy", Retry.REMOVAL, container, timeout, selectors).count;
    }

    private Answer retrieve(String operation, Retry retry, ContainerRef container, Timeout timeout,
                            Selector[] selectors) {
        Objects.requireNonNull(container, "container");
        Objects.requireNonNull(timeout, "timeout");
        for (Selector selector : selectors) {
            Objects.requireNonNull(selector, "selector");
        }
        return call(operation, timeout, retry, container, null, (out, id, wait) -> {
            out.cref("container", container).field("timeout", wait.millis()).selectors(selectors);
            if (id != null) {
                out.field("call", id);
            }
        });
    }

    @Override
    public void write(ContainerRef container, Timeout timeout, List<Item> items) {
        Objects.requireNonNull(container, "container");
        Objects.requireNonNull(timeout, "timeout");
        items.forEach(item -> Objects.requireNonNull(item, "item"));
        call("write", timeout, Retry.WRITE, container, null, (out, id, wait) -> {
            out.cref("container", container).field("timeout", wait.millis()).items(items);
            if (id != null) {
                out.field("call", id);
            }
        });
    }

    @Override
    public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
        Objects.requireNonNull(container, "container");
        Objects.requireNonNull(timeout, "timeout");
        items.forEach(item -> Objects.requireNonNull(item, "item"));
        return call("shift", Timeout.TRY_ONCE, Retry.WRITE, container, null, (out, id, wait) -> out.cref("container", container)
                .field("timeout", timeout.millis()).items(items).field("call", id)).displaced;
    }

    /**
     * One request: the server writes, then takes with the same thread, so the take waits there without a second
     * round trip. If the take's part of the wait runs out on the server (or the server stops after the write), the
     * take is asked again on its own with what is left of the timeout; the write is never repeated once it happened.
     */
    @Override
    public List<Entry> writeThenTake(ContainerRef writeTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                     Selector... selectors) {
        return putThenTake("writeThenTake", writeTo, items, takeFrom, timeout, selectors);
    }

    /** As {@link #writeThenTake}: one request, the take asked again on its own only if its wait ran out. */
    @Override
    public List<Entry> shiftThenTake(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                     Selector... selectors) {
        return putThenTake("shiftThenTake", shiftTo, items, takeFrom, timeout, selectors);
    }

    private List<Entry> putThenTake(String operation, ContainerRef writeTo, List<Item> items, ContainerRef takeFrom,
                                    Timeout timeout, Selector[] selectors) {
        Objects.requireNonNull(writeTo, "container");
        Objects.requireNonNull(takeFrom, "takeFrom");
        Objects.requireNonNull(timeout, "timeout");
        items.forEach(item -> Objects.requireNonNull(item, "item"));
        for (Selector selector : selectors) {
            Objects.requireNonNull(selector, "selector");
        }
        long start = System.nanoTime();
        Answer answer = call(operation, timeout, Retry.WRITE_THEN_TAKE, writeTo, takeFrom, (out, id, wait) -> {
            out.cref("container", writeTo).field("timeout", wait.millis()).items(items).field("call", id);
            out.field("take").startObject().cref("container", takeFrom).selectors(selectors)
                    .field("call", takeId(id)).endObject();
        });
        if (answer.more || answer.error != null || answer.outcome != null) {
            // the write happened, the take did not (yet): take on its own with what is left
            return take(takeFrom, Timeout.remaining(timeout, start), selectors);
        }
        return answer.entries;
    }

    /**
     * A take that waits without a thread: its answer is read by this client's I/O thread, which also runs
     * {@code done} (see {@link AsyncTakes}). Otherwise it behaves as {@link #take}, except that a broken connection
     * ends it with {@link SpaceUnavailableException} (after the server was asked to put back what it may have
     * taken) instead of being repeated.
     */
    @Override
    public SpaceEngine.Pending takeLater(ContainerRef container, Timeout timeout, Selector[] selectors,
                                         SpaceEngine.Completion<List<Entry>> done) {
        Objects.requireNonNull(container, "container");
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(done, "done");
        for (Selector selector : selectors) {
            Objects.requireNonNull(selector, "selector");
        }
        ensureOpen();
        AsyncCalls.Request take = takeRequest(container, selectors);
        AsyncCalls calls = asyncCalls();
        return calls.start(calls.new Call(take, null, timeout, done));
    }

    /** {@link #shiftThenTake} whose take waits without a thread; see {@link #takeLater}. */
    @Override
    public SpaceEngine.Pending shiftThenTakeLater(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom,
                                                  Timeout timeout, Selector[] selectors,
                                                  SpaceEngine.Completion<List<Entry>> done) {
        Objects.requireNonNull(shiftTo, "container");
        Objects.requireNonNull(takeFrom, "takeFrom");
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(done, "done");
        items.forEach(item -> Objects.requireNonNull(item, "item"));
        for (Selector selector : selectors) {
            Objects.requireNonNull(selector, "selector");
        }
        ensureOpen();
        AsyncCalls.Request composite = new AsyncCalls.Request() {
            @Override
            public String operation() {
                return "shiftThenTake";
            }

            @Override
            public ContainerRef container() {
                return shiftTo;
            }

            @Override
            public ContainerRef takesFrom() {
                return takeFrom;
            }

            @Override
            public byte[] encode(String callId, Timeout wait, boolean binary) {
                return RemoteSpace.this.encode((out, id, w) -> {
                    out.cref("container", shiftTo).field("timeout", w.millis()).items(items).field("call", id);
                    out.field("take").startObject().cref("container", takeFrom).selectors(selectors)
                            .field("call", takeId(id)).endObject();
                }, callId, wait, binary);
            }
        };
        AsyncCalls calls = asyncCalls();
        return calls.start(calls.new Call(composite, takeRequest(takeFrom, selectors), timeout, done));
    }

    private AsyncCalls.Request takeRequest(ContainerRef container, Selector[] selectors) {
        return new AsyncCalls.Request() {
            @Override
            public String operation() {
                return "take";
            }

            @Override
            public ContainerRef container() {
                return container;
            }

            @Override
            public byte[] encode(String callId, Timeout wait, boolean binary) {
                return RemoteSpace.this.encode((out, id, w) -> out.cref("container", container)
                        .field("timeout", w.millis()).selectors(selectors).field("call", id), callId, wait, binary);
            }
        };
    }

    private synchronized AsyncCalls asyncCalls() {
        ensureOpen();
        if (asyncCalls == null) {
            try {
                asyncCalls = new AsyncCalls(this);
            } catch (IOException e) {
                throw new SpaceException("cannot start the space client's I/O thread: " + e.getMessage(), e);
            }
        }
        return asyncCalls;
    }

    // ---- for AsyncCalls ----

    String newCallId() {
        return clientId + ":" + lastCall.incrementAndGet();
    }

    /** Records (or forgets) a call that waits on the server, so that close() cancels it there. */
    void waiting(String callId, boolean add) {
        if (add) {
            waitingCalls.put(callId, Boolean.TRUE);
        } else {
            waitingCalls.remove(callId);
        }
    }

    AckQueue acks() {
        return acks;
    }

    long allowanceNanos() {
        return TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis());
    }

    ScheduledExecutorService timer() {
        return timer;
    }

    /** Whether a request of {@code operation} in a frame goes in the binary form (the server reads it). */
    boolean binaryBodies(String operation) {
        return binaryBodies && BinaryWire.OPERATIONS.contains(operation);
    }

    /** Whether new connections to the current server carry operations as frames. */
    boolean framesOffered() {
        return pool.framed();
    }

    /** {@code server} answered an upgrade to frames as a plain GET: it is not asked for frames again. */
    void framesRefused(Endpoint server) {
        int index = endpoints.indexOf(server);
        if (index >= 0) {
            pools.get(index).noFrames();
        }
    }

    /** A complete HTTP request for {@code operation}, as one byte array. */
    byte[] requestBytes(String operation, String ackHeader, byte[] body) {
        byte[] head = ("POST " + endpoint.path(operation) + " HTTP/1.1\r\nHost: " + endpoint.hostHeader()
                + "\r\nContent-Type: application/json\r\nContent-Length: " + body.length + "\r\n"
                + headers(ackHeader) + "\r\n").getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
        byte[] message = java.util.Arrays.copyOf(head, head.length + body.length);
        System.arraycopy(body, 0, message, head.length, body.length);
        return message;
    }

    /**
     * Asks the server to cancel a call (a lost take's entries go back at once, not when their hold runs out); one try
     * per server within the network allowance: a server that does not answer moves the client on to the next one.
     */
    void cancelQuietly(String callId) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis());
        for (int i = 0; i < endpoints.size() && !closed && System.nanoTime() - deadline < 0; i++) {
            if (exchangeQuietly("cancel", null, callId, deadline) != null) {
                return;
            }
        }
    }

    /** The call id of the take of a writeThenTake whose write has id {@code callId}. */
    static String takeId(String callId) {
        return callId + ".t";
    }

    /**
     * How a call is named when it is acknowledged or cancelled: {@code id/containerId}, so that a server that never
     * saw the call (this client failed over to it) settles it on its container at once instead of asking every
     * container of a clustered space; the plain id where there is no container or its id is not wire-safe.
     */
    static String settleRef(String callId, ContainerRef container) {
        return container == null || !Wire.isId(container.id()) ? callId
                : callId + "/" + container.id();
    }

    // ---- notifications ----

    @Override
    public Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode,
                                  Timeout timeout, NotificationListener listener) {
        Objects.requireNonNull(container, "container");
        Objects.requireNonNull(operations, "operations");
        Objects.requireNonNull(mode, "mode");
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(listener, "listener");
        ensureOpen();
        RemoteSubscription subscription = new RemoteSubscription(container, operations, mode, timeout, listener,
                options.notificationQueue(), delivery, this::cancelOnServer);
        events.subscribe(subscription, System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis()));
        return subscription;
    }

    /** Establishes {@code subscription} on the stream {@code session}; the answer has the server's id and sequence. */
    Answer subscribeOnServer(String session, RemoteSubscription subscription, Timeout timeout) {
        return call("subscribe", null, Retry.IDEMPOTENT, (out, id, wait) -> out.field("session", session)
                .cref("container", subscription.container).operations(subscription.operations)
                .field("mode", Wire.name(subscription.mode)).field("timeout", timeout.millis()));
    }

    private void cancelOnServer(RemoteSubscription subscription) {
        String session = events.sessionId();
        String serverId = subscription.serverId;
        if (subscription.session == null || serverId == null || closed) {
            subscription.end(SubscriptionEnd.CANCELLED); // not established now: nothing can arrive any more
            events.forget(subscription);
            return;
        }
        try {
            call("unsubscribe", null, Retry.IDEMPOTENT, (out, id, wait) -> out.field("session", session)
                    .field("subscription", serverId));
        } catch (SpaceException e) {
            subscription.end(SubscriptionEnd.CANCELLED);
            events.forget(subscription);
        }
    }

    // ---- lifecycle ----

    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        acks.close(); // what is left goes below
        pools.forEach(ConnectionPool::close); // breaks the waits of calls in progress: SpaceClosedException
        synchronized (this) {
            if (asyncCalls != null) {
                asyncCalls.close(); // takes waiting without a thread end with SpaceClosedException
            }
        }
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(Math.min(options.networkAllowanceMillis(), 1000));
        String pending;
        while ((pending = acks.drain()) != null && System.nanoTime() < deadline) {
            exchangeQuietly("ack", pending, null, deadline); // confirm received takes, or they come back
        }
        for (String callId : waitingCalls.keySet()) {
            exchangeQuietly("cancel", null, callId, deadline); // do not leave our waits behind on the server
        }
        if (events.started()) {
            // end the notification session now rather than after the server's grace period
            postQuietly("endSession", encode((out, id, wait) -> out.field("session", events.sessionId()), null,
                    Timeout.TRY_ONCE), null, deadline);
        }
        events.close();
        timer.shutdownNow();
        delivery.shutdown();
    }

    boolean isClosed() {
        return closed;
    }

    private void ensureOpen() {
        if (closed) {
            throw new SpaceClosedException("the remote space " + endpoint.url() + " is closed");
        }
    }

    @Override
    public String toString() {
        return "RemoteSpace[" + endpoint.url() + "]";
    }

    // ---- calls ----

    /** How a call may be repeated after the connection broke before its answer arrived. */
    enum Retry {
        /** Repeating does no harm. */
        IDEMPOTENT,
        /** take/destroy: cancel the lost call (its entries go back), then repeat. */
        REMOVAL,
        /** write and shift: ask whether the lost call happened; repeat only if it did not. */
        WRITE,
        /** writeThenTake: cancel the take (its entries go back), then as {@link #WRITE} for the write. */
        WRITE_THEN_TAKE,
        /** The outcome cannot be learned: fail with {@link SpaceUnavailableException}. */
        UNSAFE
    }

    /** Writes a request body's fields (inside the object) for a call id and the timeout left. */
    @FunctionalInterface
    interface Body {
        void write(WireWriter out, String callId, Timeout wait);
    }

    /**
     * One call with its retries.
     *
     * @param timeout the operation's timeout, or null for calls that do not wait
     */
    Answer call(String operation, Timeout timeout, Retry retry, Body body) {
        return call(operation, timeout, retry, null, null, body);
    }

    /**
     * As {@link #call(String, Timeout, Retry, Body)} for a call on a container.
     *
     * @param on     the container the call runs on, named when it is settled (null: none)
     * @param takeOn the container of a writeThenTake's take (null for other calls)
     */
    Answer call(String operation, Timeout timeout, Retry retry, ContainerRef on, ContainerRef takeOn, Body body) {
        ensureOpen();
        long start = System.nanoTime();
        boolean waits = timeout != null && !timeout.isTryOnce();
        boolean infinite = timeout != null && timeout.isInfinite();
        long allowance = TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis());
        long operationDeadline = timeout == null || infinite ? start : start + TimeUnit.MILLISECONDS.toNanos(timeout.millis());
        long networkDeadline = operationDeadline + allowance;
        boolean needsId = retry != Retry.IDEMPOTENT && retry != Retry.UNSAFE || waits;
        boolean composite = retry == Retry.WRITE_THEN_TAKE;
        Exception lastFailure = null;
        int attempt = 0;
        while (true) {
            ensureOpen();
            long now = System.nanoTime();
            Timeout wait = timeout == null ? Timeout.TRY_ONCE : infinite ? Timeout.INFINITE
                    : waitLeft(operationDeadline - now);
            String callId = needsId ? clientId + ":" + lastCall.incrementAndGet() : null;
            String ref = callId == null ? null : settleRef(callId, on);
            String takeRef = callId == null ? null : settleRef(takeId(callId), takeOn);
            long serverWait = wait.isInfinite() ? serverMaxWaitMillis : Math.min(wait.millis(), serverMaxWaitMillis);
            long readDeadline = now + TimeUnit.MILLISECONDS.toNanos(serverWait) + allowance;
            Endpoint used = endpoint; // the server of this attempt (a failover may change it meanwhile)
            ConnectionPool pool = this.pool;
            HttpConnection connection = null;
            boolean sent = false;
            String ackHeader = acks.drain();
            if (waits) {
                waitingCalls.put(ref, Boolean.TRUE);
                if (composite) {
                    waitingCalls.put(takeRef, Boolean.TRUE);
                }
            }
            try {
                connection = pool.borrow(infinite ? readDeadline : Math.min(readDeadline, networkDeadline));
                byte[] request = encode(body, callId, wait, connection.framed && binaryBodies(operation));
                connection.sendOperation(used, operation, ackHeader, request, request.length);
                sent = true;
                HttpConnection.Response response = connection.receive(readDeadline, waits ? RemoteSpace::checkInterrupt
                        : () -> { });
                pool.release(connection);
                Answer answer = parseAnswer(response);
                if (answer.error != null) {
                    WireError kind = WireError.byKind(answer.error);
                    if (kind == WireError.UNAVAILABLE) {
                        connection = null; // back in the pool: the exchange itself went well
                        throw new ServerUnavailable(answer.message);
                    }
                    if (kind == WireError.STOPPING || kind == WireError.BUSY) {
                        // a request refused as it arrived had its confirmations unread: they go again (twice is
                        // harmless, never is not: the takes would come back after their lease and be taken twice)
                        acks.requeue(ackHeader);
                        if (kind == WireError.STOPPING) {
                            failover(used, true, "it is stopping"); // another server of the space (if any) goes on
                        }
                        if (answer.written) {
                            return answer; // the write happened: the caller takes on its own
                        }
                        lastFailure = new SpaceUnavailableException(used.url(), answer.message, null);
                        pool.discardIdle();
                    } else {
                        throw failure(response.status(), kind, answer);
                    }
                } else if (answer.more) {
                    if (answer.written) {
                        return answer; // the write happened: the caller takes on its own
                    }
                    if (!infinite && System.nanoTime() - operationDeadline >= 0) {
                        throw new SpaceTimeoutException("timed out after " + timeout + " on " + operation);
                    }
                    attempt = 0;
                    continue; // the server's wait ran out before ours: ask again
                } else {
                    if (answer.ack) {
                        acks.add(composite ? takeRef : ref);
                    }
                    return answer;
                }
            } catch (CallerInterrupted interrupt) {
                // only the caller's interrupt: a socket timeout (an InterruptedIOException too) means an unreachable
                // or silent server, and is handled below like any other broken exchange
                pool.discard(connection);
                acks.requeue(ackHeader);
                return interrupted(operation, ref, takeRef, retry);
            } catch (IOException e) {
                if (connection != null) {
                    pool.discard(connection);
                }
                acks.requeue(ackHeader);
                if (closed) {
                    if (waits) {
                        exchangeQuietly("cancel", null, ref, System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(200));
                    }
                    throw new SpaceClosedException("the remote space " + endpoint.url() + " was closed during "
                            + operation);
                }
                // a keep-alive connection the server closed while idle fails like this too; only calls whose
                // outcome cannot be asked about rely on that guess
                boolean stale = !(e instanceof ServerUnavailable) && closedWhileIdle(connection);
                pool.discardIdle(); // a broken connection usually means they are all broken (server restart)
                if (!stale) {
                    failover(used, e); // with several servers, settle and repeat the call with the next one
                }
                if (sent && (retry == Retry.REMOVAL || retry == Retry.WRITE || composite || !stale)) {
                    Answer settled = settleLostCall(operation, ref, takeRef, retry, networkDeadline, e);
                    if (settled != null) {
                        return settled;
                    }
                }
                if (stale) {
                    attempt = 0; // a keep-alive connection the server had closed: retry at once
                }
                lastFailure = e;
            } finally {
                if (waits) {
                    waitingCalls.remove(ref);
                    if (composite) {
                        waitingCalls.remove(takeRef);
                    }
                }
            }
            if (!infinite && System.nanoTime() - networkDeadline >= 0) {
                throw new SpaceUnavailableException(used.url(), "cannot reach the space server for " + operation,
                        lastFailure);
            }
            backOff(attempt++, waits, infinite ? Long.MAX_VALUE : networkDeadline);
        }
    }

    /**
     * After the connection broke with the request sent: makes a repeat safe, or gives up.
     *
     * @param callId  the call's settle reference
     * @param takeRef the settle reference of a writeThenTake's take
     */
    private Answer settleLostCall(String operation, String callId, String takeRef, Retry retry, long deadline,
                                  IOException cause) {
        switch (retry) {
            case IDEMPOTENT:
                return null;
            case REMOVAL:
                // if it happened, its entries go back (now, not when their hold runs out: the repeated call or
                // another caller may be waiting for them); repeated until a server answers, the next one if the
                // last one failed
                cancelUntil(callId, deadline);
                return null;
            case WRITE_THEN_TAKE:
                cancelUntil(takeRef, deadline); // the take never counts: its entries go back
                // then as a write: "completed" tells the caller to take on its own
                return settleLostCall(operation, callId, takeRef, Retry.WRITE, deadline, cause);
            case WRITE:
                Answer outcome = cancelUntil(callId, deadline);
                if (outcome != null && "completed".equals(outcome.outcome)) {
                    return outcome; // it happened (for a shift, with what it displaced)
                }
                if (outcome == null) {
                    throw new SpaceUnavailableException(endpoint.url(), operation
                            + ": the connection broke before the answer, and whether it happened is unknown", cause);
                }
                return null;
            default:
                throw new SpaceUnavailableException(endpoint.url(), operation
                        + ": the connection broke before the answer, so whether it happened is unknown", cause);
        }
    }

    /** The waiting thread was interrupted: cancel on the server (by settle references), then report. */
    private Answer interrupted(String operation, String callId, String takeRef, Retry retry) {
        Thread.interrupted(); // talk to the server undisturbed; the flag is set again below
        try {
            if (retry == Retry.WRITE_THEN_TAKE) {
                // the take is undone; the write is left as it is (the caller learns that it may have happened)
                exchangeQuietly("cancel", null, takeRef, System.nanoTime()
                        + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis()));
            }
            Answer outcome = exchangeQuietly("cancel", null, callId, System.nanoTime()
                    + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis()));
            if (retry == Retry.WRITE && outcome != null && "completed".equals(outcome.outcome)) {
                return outcome; // it happened: hand that over rather than pretend it did not
            }
            throw new SpaceInterruptedException("interrupted while waiting in " + operation + " on " + endpoint.url(),
                    new InterruptedException());
        } finally {
            Thread.currentThread().interrupt();
        }
    }

    private Answer cancelUntil(String callId, long deadline) {
        int attempt = 0;
        while (System.nanoTime() - deadline < 0) {
            // the call's own bound: no grace past it (a lost answer is then reported as unknown)
            Answer outcome = exchangeQuietly("cancel", null, callId, deadline, false);
            if (outcome != null) {
                return outcome;
            }
            backOff(attempt++, false, deadline);
        }
        return null;
    }

    /** One exchange without retries, for acks and cancels (also after close): the answer, or null on failure. */
    private Answer exchangeQuietly(String operation, String ackHeader, String callId, long deadline) {
        return exchangeQuietly(operation, ackHeader, callId, deadline, true);
    }

    /** As above; {@code grace}: the answer may come up to 100 ms past the deadline (clean-ups, not calls). */
    private Answer exchangeQuietly(String operation, String ackHeader, String callId, long deadline, boolean grace) {
        byte[] request = callId == null ? "{}".getBytes(java.nio.charset.StandardCharsets.US_ASCII)
                : encode((out, id, wait) -> out.field("call", callId), null, Timeout.TRY_ONCE);
        return postQuietly(operation, request, ackHeader, deadline, grace);
    }

    private Answer postQuietly(String operation, byte[] request, String ackHeader, long deadline) {
        return postQuietly(operation, request, ackHeader, deadline, true);
    }

    private Answer postQuietly(String operation, byte[] request, String ackHeader, long deadline, boolean grace) {
        HttpConnection connection = null;
        Endpoint used = endpoint;
        try {
            connection = new HttpConnection(used.host(), used.port(), pool.connectTimeout(deadline));
            connection.sendOperation(used, operation, ackHeader, request, request.length);
            HttpConnection.Response response = connection.receive(grace ? Math.max(deadline,
                    System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(100)) : deadline, () -> { });
            if (response.status() != 200) {
                return null;
            }
            return parseAnswer(response);
        } catch (IOException e) {
            if (!closed) {
                failover(used, e); // a cancel or confirmation that cannot reach its server goes to the next one
            }
            return null;
        } catch (SpaceException e) {
            return null;
        } finally {
            if (connection != null) {
                connection.close();
            }
        }
    }

    /** Whether a failed exchange most likely met a pooled connection the server had closed while it was idle. */
    private static boolean closedWhileIdle(HttpConnection connection) {
        return connection != null && connection.reused && !connection.hasBufferedInput();
    }

    private boolean sendAcks(String header) {
        if (closed) {
            return true; // close() sends what is left
        }
        HttpConnection connection = null;
        Endpoint used = endpoint;
        ConnectionPool pool = this.pool;
        try {
            connection = pool.borrow(System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis()));
            byte[] body = {'{', '}'};
            connection.sendOperation(used, "ack", header, body, body.length);
            HttpConnection.Response response = connection.receive(System.nanoTime()
                    + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis()), () -> { });
            pool.release(connection);
            return response.status() == 200;
        } catch (IOException e) {
            // a pooled connection the server closed while it was idle fails like this too: not a reason to move on
            boolean stale = closedWhileIdle(connection);
            if (connection != null) {
                pool.discard(connection);
            }
            if (stale) {
                pool.discardIdle(); // the acks are sent again on a fresh connection
            } else {
                failover(used, e);
            }
            return false;
        }
    }

    /**
     * Asks a server which space it serves and its limits, trying the servers in turn within the network allowance;
     * all of them must serve the same space.
     */
    private void hello() {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.networkAllowanceMillis());
        Exception lastFailure = null;
        int attempt = 0;
        while (true) {
            Endpoint used = endpoint;
            ConnectionPool pool = this.pool;
            HttpConnection connection = null;
            try {
                connection = pool.borrowHttp(deadline); // the description is an HTTP request, never a frame
                connection.send("GET", used.basePath(), used.authorization(), null, 0);
                HttpConnection.Response response = connection.receive(deadline, () -> { });
                pool.release(connection);
                Answer answer = parseAnswer(response);
                if (answer.error != null) {
                    throw failure(response.status(), WireError.byKind(answer.error), answer);
                }
                if (answer.space == null) {
                    throw new WireFormatException("the server did not say which space it serves");
                }
                spaceUri = URI.create(answer.space);
                if (answer.maxWait > 0) {
                    serverMaxWaitMillis = answer.maxWait;
                }
                if (answer.frames >= 1 && options.frames()) {
                    // the servers of one space run the same version: all of them take frames
                    pools.forEach(ConnectionPool::useFrames);
                    binaryBodies = answer.binary >= BinaryWire.VERSION && options.binary();
                }
                return;
            } catch (IOException e) {
                if (connection != null) {
                    pool.discard(connection);
                }
                lastFailure = e;
                failover(used, e);
            }
            if (System.nanoTime() - deadline >= 0) {
                throw new SpaceUnavailableException(used.url(), endpoints.size() == 1 ? "cannot reach the space server"
                        : "cannot reach any of the " + endpoints.size() + " space servers " + urls(), lastFailure);
            }
            backOff(attempt++, false, deadline);
        }
    }

    // ---- helpers ----

    /**
     * The wait the server is given for what is left of a call's timeout, rounded up to whole milliseconds: rounded
     * down, a take could time out up to a millisecond before the timeout its caller gave.
     */
    static Timeout waitLeft(long nanosLeft) {
        return Timeout.ofMillis(nanosLeft <= 0 ? 0 : (nanosLeft + 999_999) / 1_000_000);
    }

    private String headers(String ackHeader) {
        return headers(endpoint, ackHeader);
    }

    private static String headers(Endpoint to, String ackHeader) {
        return ackHeader == null ? to.authorization()
                : to.authorization() + Wire.ACK_HEADER + ": " + ackHeader + "\r\n";
    }

    private byte[] encode(Body body, String callId, Timeout wait) {
        return encode(body, callId, wait, false);
    }

    /** A request body: in the binary form if {@code binary}, else JSON. */
    private byte[] encode(Body body, String callId, Timeout wait, boolean binary) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(128);
        try (WireWriter out = binary ? WireWriter.binary(wire.crefs(), bytes) : wire.writer(bytes)) {
            out.startObject();
            body.write(out, callId, wait);
            out.endObject();
        }
        return bytes.toByteArray();
    }

    private Answer parseAnswer(HttpConnection.Response response) {
        try {
            return Answer.parse(wire, response.body());
        } catch (WireFormatException e) {
            if (response.status() != 200) {
                // not one of our error bodies (e.g. the servlet container's own page)
                throw new SpaceRequestRejectedException(response.status(), "the server refused the request with HTTP "
                        + response.status());
            }
            throw e;
        }
    }

    SpaceException failure(int status, WireError kind, Answer answer) {
        String message = answer.message == null ? answer.error : answer.message;
        if (kind == WireError.NO_SESSION) {
            return new SessionGoneException(message);
        }
        if (kind == null) {
            return new SpaceRequestRejectedException(status, answer.error + ": " + message);
        }
        return kind.toException(message);
    }

    private static void checkInterrupt() throws InterruptedIOException {
        if (Thread.currentThread().isInterrupted()) {
            throw new CallerInterrupted();
        }
    }

    /**
     * The server answered that it could not complete the call (its cluster is recovering): handled like a broken
     * connection, since whether the call took effect is not known.
     */
    private static final class ServerUnavailable extends IOException {
        private static final long serialVersionUID = 1L;

        ServerUnavailable(String message) {
            super("the server could not complete the call: " + message);
        }
    }

    /** The calling thread was interrupted while its call waited: told apart from socket timeouts on purpose. */
    private static final class CallerInterrupted extends InterruptedIOException {
        private static final long serialVersionUID = 1L;

        CallerInterrupted() {
            super("interrupted");
        }
    }

    /** Waits before a retry: 5 ms, doubling to 250 ms, never past the deadline. */
    private static void backOff(int attempt, boolean interruptible, long deadline) {
        long millis = Math.min(BACKOFF_MAX_MILLIS, (long) BACKOFF_FIRST_MILLIS << Math.min(attempt, 10));
        long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
        millis = Math.max(1, Math.min(millis, left));
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            if (interruptible) {
                throw new SpaceInterruptedException("interrupted while waiting for the space server", e);
            }
        }
    }

    static ThreadFactory daemonThreads(String prefix) {
        AtomicInteger count = new AtomicInteger();
        return task -> {
            Thread thread = new Thread(task, prefix + "-" + count.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        };
    }

    Endpoint endpoint() {
        return endpoint;
    }

    /** A subscription request named a stream that is gone; the caller waits for the new one and repeats. */
    static final class SessionGoneException extends SpaceException {
        SessionGoneException(String message) {
            super(message);
        }
    }

    /**
     * How a client behaves. Start from {@link #defaults()}.
     *
     * @param token                  bearer token to send, or null
     * @param networkAllowanceMillis how long past its timeout a call may take because of the network (and how long
     *                               calls that do not wait keep retrying an unreachable server)
     * @param connectTimeoutMillis   how long one connection attempt may take
     * @param notificationQueue      undelivered notifications each subscription may queue before it overflows
     * @param maxIdleConnections     keep-alive connections kept open for reuse
     * @param ackDelayMicros         how long a take's confirmation may wait for another request to ride on
     * @param frames                 whether operations go as frames to a server that offers them (the same
     *                               requests without HTTP's request line and headers); false: always HTTP
     * @param binary                 whether the bodies of the hot operations go in the compact binary form to a
     *                               server that reads it (in frames only); false: always JSON
     */
    public record Options(String token, long networkAllowanceMillis, int connectTimeoutMillis, int notificationQueue,
                          int maxIdleConnections, long ackDelayMicros, boolean frames, boolean binary) {

        /** Validates the values. */
        public Options {
            if (networkAllowanceMillis < 1 || connectTimeoutMillis < 1 || notificationQueue < 1
                    || maxIdleConnections < 0 || ackDelayMicros < 0) {
                throw new IllegalArgumentException("client times and sizes must be positive");
            }
        }

        /**
         * No token, 3 s network allowance, 1 s connect timeout, 10 000 queued notifications, 32 idle connections,
         * and take confirmations sent alone after 20 ms without another request (they usually ride on the next one),
         * operations as frames where the server offers them, with the hot operations' bodies in the binary form where
         * the server reads it.
         */
        public static Options defaults() {
            return new Options(null, 3_000, 1_000, 10_000, 32, 20_000, true, true);
        }

        /** With a bearer token. */
        public Options token(String newToken) {
            return new Options(newToken, networkAllowanceMillis, connectTimeoutMillis, notificationQueue,
                    maxIdleConnections, ackDelayMicros, frames, binary);
        }

        /** With another network allowance. */
        public Options networkAllowanceMillis(long millis) {
            return new Options(token, millis, connectTimeoutMillis, notificationQueue, maxIdleConnections,
                    ackDelayMicros, frames, binary);
        }

        /** With another per-subscription notification queue. */
        public Options notificationQueue(int capacity) {
            return new Options(token, networkAllowanceMillis, connectTimeoutMillis, capacity, maxIdleConnections,
                    ackDelayMicros, frames, binary);
        }

        /** With another connect timeout. */
        public Options connectTimeoutMillis(int millis) {
            return new Options(token, networkAllowanceMillis, millis, notificationQueue, maxIdleConnections,
                    ackDelayMicros, frames, binary);
        }

        /** With another number of idle keep-alive connections. */
        public Options maxIdleConnections(int connections) {
            return new Options(token, networkAllowanceMillis, connectTimeoutMillis, notificationQueue, connections,
                    ackDelayMicros, frames, binary);
        }

        /** With operations as frames where the server offers them (true), or always as HTTP requests (false). */
        public Options frames(boolean useFrames) {
            return new Options(token, networkAllowanceMillis, connectTimeoutMillis, notificationQueue,
                    maxIdleConnections, ackDelayMicros, useFrames, binary);
        }

        /** With the hot operations' bodies in the binary form where the server reads it (true), or JSON (false). */
        public Options binary(boolean useBinary) {
            return new Options(token, networkAllowanceMillis, connectTimeoutMillis, notificationQueue,
                    maxIdleConnections, ackDelayMicros, frames, useBinary);
        }

        /** With another delay before a take's confirmation is sent on its own. */
        public Options ackDelayMicros(long micros) {
            return new Options(token, networkAllowanceMillis, connectTimeoutMillis, notificationQueue,
                    maxIdleConnections, micros, frames, binary);
        }
    }
}
