package robotworld.space.remote;

import java.io.EOFException;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;

import robotworld.space.ContainerRef;
import robotworld.space.Entry;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.Timeout;
import robotworld.space.wire.Frames;
import robotworld.space.wire.WireError;

/**
 * The client's waits without threads: takes (and shift-then-takes) whose answers are read by one I/O thread
 * ({@code space-client-io}) with non-blocking sockets, however many of them wait. Each waiting call holds one
 * keep-alive connection (HTTP/1.1 has one request in flight per connection) and a few small objects; its completion
 * runs on the I/O thread and must not block.
 *
 * <p>A call behaves like a blocking take of {@link RemoteSpace}: a server wait that ran out ({@code "more"}) is
 * asked again with what is left of the timeout; {@code busy} and {@code stopping} are retried with a growing pause;
 * a take's removal is confirmed like any other. A broken connection or an overdue answer ends the call with
 * {@link SpaceUnavailableException} after asking the server to put back what the lost take may have removed (the
 * caller decides whether to try again; for a shift-then-take whether the shift happened is then unknown).
 */
final class AsyncCalls implements Runnable {

    private static final System.Logger LOG = System.getLogger(AsyncCalls.class.getName());
    private static final int MAX_IDLE = 64;
    private static final long CHECK_NANOS = TimeUnit.MILLISECONDS.toNanos(25);

    private final RemoteSpace owner;
    private final java.nio.channels.Selector selector;
    private final ConcurrentLinkedQueue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    /** Calls whose request is out (or going out), for the deadline checks. */
    private final Set<Call> active = ConcurrentHashMap.newKeySet();
    /**
     * Connections kept for reuse, registered for reading (so a close by the server is noticed), each with the
     * server it goes to: after a failover, one to the server just left is never reused, even before
     * {@link #endpointChanged} has closed them.
     */
    private final ConcurrentLinkedDeque<IdleChannel> idle = new ConcurrentLinkedDeque<>();
    private Thread thread;
    private volatile boolean closed;

    AsyncCalls(RemoteSpace owner) throws IOException {
        this.owner = owner;
        this.selector = java.nio.channels.Selector.open();
    }

    /**
     * Starts a call; its outcome goes to its completion. On a thread other than the I/O thread (a provider's serving
     * thread sending an answer and its next take) the request goes out at once on an idle connection, so the I/O
     * thread is not woken for it; it only reads the answer.
     */
    SpaceEngine.Pending start(Call call) {
        if (thread != null && Thread.currentThread() != thread && !closed && call.sendDirect()) {
            return call;
        }
        execute(call::send);
        return call;
    }

    private void execute(Runnable task) {
        synchronized (this) {
            if (closed) {
                throw new SpaceClosedException("the remote space " + owner.url() + " is closed");
            }
            if (thread == null) {
                thread = new Thread(this, "space-client-io");
                thread.setDaemon(true);
                thread.start();
            }
        }
        tasks.add(task);
        selector.wakeup();
    }

    /** Ends every waiting call with {@link SpaceClosedException}; their ids are left for the owner to cancel. */
    void close() {
        synchronized (this) {
            closed = true;
        }
        selector.wakeup();
    }

    /** The client moved on to another server: idle connections to the old one are of no use any more. */
    void endpointChanged() {
        execute(() -> {
            IdleChannel unused;
            while ((unused = idle.pollFirst()) != null) {
                closeQuietly(unused.channel());
            }
        });
    }

    /** An idle connection, the server it goes to, and whether it carries frames. */
    private record IdleChannel(SocketChannel channel, Endpoint endpoint, boolean framed) {
    }

    /** The most recently used idle connection to the client's current server, closing any to other servers. */
    private IdleChannel pollIdle() {
        IdleChannel candidate;
        while ((candidate = idle.pollFirst()) != null) {
            if (candidate.endpoint() == owner.endpoint()) {
                return candidate;
            }
            closeQuietly(candidate.channel()); // closing cancels its key: safe from any thread
        }
        return null;
    }

    @Override
    public void run() {
        long nextCheck = System.nanoTime() + CHECK_NANOS;
        try {
            while (!closed) {
                selector.select(25);
                Runnable task;
                while ((task = tasks.poll()) != null) {
                    task.run();
                }
                for (SelectionKey key : selector.selectedKeys()) {
                    if (key.attachment() instanceof Call call && key.isValid()) {
                        call.ready(key);
                    } else if (key.isValid() && key.isReadable()) {
                        closeIdle((SocketChannel) key.channel()); // an idle connection closed by the server
                    }
                }
                selector.selectedKeys().clear();
                long now = System.nanoTime();
                if (now - nextCheck >= 0) {
                    nextCheck = now + CHECK_NANOS;
                    // the set's iterator tolerates the removals and additions a check makes: no copy of a set that
                    // holds every waiting call (a thousand with a thousand waiting modules), every 25 ms
                    for (Call call : active) {
                        call.checkDeadline(now);
                    }
                }
            }
        } catch (IOException | RuntimeException e) {
            LOG.log(System.Logger.Level.WARNING, "the space client's I/O thread failed", e);
        } finally {
            closed = true;
            for (Call call : List.copyOf(active)) {
                call.finish(null, new SpaceClosedException("the remote space " + owner.url() + " was closed"));
            }
            idle.forEach(unused -> closeQuietly(unused.channel()));
            try {
                selector.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
    }

    private void closeIdle(SocketChannel channel) {
        idle.removeIf(unused -> unused.channel() == channel);
        closeQuietly(channel);
    }

    private static void closeQuietly(SocketChannel channel) {
        try {
            channel.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    /** How a call's request body is written: the operation, and the fields for a call id and the wait left. */
    interface Request {
        String operation();

        /** The body, in the binary form if {@code binary} (else JSON). */
        byte[] encode(String callId, Timeout wait, boolean binary);

        /** The container the call runs on (a shift-then-take's shift), named when the call is settled. */
        ContainerRef container();

        /** The container the call takes from. */
        default ContainerRef takesFrom() {
            return container();
        }
    }

    /** One take (or shift-then-take) waiting without a thread. */
    final class Call implements SpaceEngine.Pending {

        private Request request;
        private boolean composite;
        private final Request take;
        private final Timeout timeout;
        private final SpaceEngine.Completion<List<Entry>> done;
        private final long operationDeadline;
        // the fields below belong to the thread sending the request, then to the I/O thread
        private String callId;
        /** How the call and its take are named when settled ({@link RemoteSpace#settleRef}). */
        private String ref;
        private String takeRef;
        private String ackHeader;
        private SocketChannel channel;
        private SelectionKey key;
        private ByteBuffer out;
        private ByteBuffer in = ByteBuffer.allocate(4096);
        /** The wait left for this attempt; its body is written once the connection is known. */
        private Timeout waitLeft;
        /** This call's connection carries frames. */
        private boolean framed;
        /** Its answer starts with the 101 of the upgrade to frames sent before the request. */
        private boolean awaitingUpgrade;
        private long ioDeadline;
        /** How long the answer may take once the request is out: the server's wait plus the network allowance. */
        private long answerNanos;
        private volatile boolean sent;
        private boolean reused;
        private int attempt;
        /** RUNNING, then DONE or CANCELLED; guarded by this. */
        private int state;

        /**
         * @param request the first request (a take, or a shift-then-take)
         * @param take    the plain take to go on with after a shift-then-take's shift happened, or null
         */
        Call(Request request, Request take, Timeout timeout, SpaceEngine.Completion<List<Entry>> done) {
            this.request = request;
            this.take = take;
            this.composite = take != null;
            this.timeout = timeout;
            this.done = done;
            this.operationDeadline = timeout.isInfinite() ? 0
                    : System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeout.millis());
        }

        private synchronized boolean running() {
            return state == 0;
        }

        /** Sends the request (again), on a pooled connection or a new one. I/O thread. */
        void send() {
            if (!running()) {
                return;
            }
            if (closed) {
                finish(null, new SpaceClosedException("the remote space " + owner.url() + " is closed"));
                return;
            }
            long now = System.nanoTime();
            prepare(now);
            active.add(this);
            try {
                IdleChannel reusable = pollIdle();
                reused = reusable != null;
                if (reused) {
                    channel = reusable.channel();
                    connectedTo = reusable.endpoint();
                    encode(reusable.framed(), false);
                } else {
                    channel = SocketChannel.open();
                    channel.configureBlocking(false);
                    channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
                    channel.setOption(StandardSocketOptions.SO_KEEPALIVE, true);
                    Endpoint endpoint = owner.endpoint();
                    connectedTo = endpoint;
                    boolean frames = owner.framesOffered();
                    encode(frames, frames); // the upgrade and the first frame in one write
                    if (!channel.connect(new InetSocketAddress(endpoint.host(), endpoint.port()))) {
                        key = channel.register(selector, SelectionKey.OP_CONNECT, this);
                        ioDeadline = Math.min(ioDeadline,
                                now + TimeUnit.MILLISECONDS.toNanos(owner.options.connectTimeoutMillis()));
                        return;
                    }
                }
                key = channel.register(selector, 0, this);
                write();
            } catch (IOException e) {
                broken(e);
            }
        }

        /**
         * Sends the request from this (non-I/O) thread on an idle connection, which stays registered for reading;
         * false if there is none.
         */
        boolean sendDirect() {
            if (!running()) {
                return true;
            }
            IdleChannel reusable = pollIdle();
            if (reusable == null) {
                return false;
            }
            SocketChannel idleChannel = reusable.channel();
            SelectionKey idleKey = idleChannel.keyFor(selector);
            if (idleKey == null || !idleKey.isValid()) {
                closeQuietly(idleChannel);
                return false;
            }
            prepare(System.nanoTime());
            channel = idleChannel;
            connectedTo = reusable.endpoint();
            encode(reusable.framed(), false);
            key = idleKey;
            reused = true;
            active.add(this);
            idleKey.attach(this); // publishes this call's fields to the I/O thread before any answer can arrive
            try {
                idleChannel.write(out);
                if (out.hasRemaining()) {
                    execute(() -> {
                        if (key == idleKey && idleKey.isValid()) {
                            idleKey.interestOps(SelectionKey.OP_WRITE);
                        }
                    });
                } else {
                    sent = true;
                }
            } catch (IOException e) {
                execute(() -> broken(e));
            }
            return true;
        }

        /** A new call id and request; the fields every send starts from. */
        private void prepare(long now) {
            Timeout wait = timeout.isInfinite() ? Timeout.INFINITE
                    : RemoteSpace.waitLeft(operationDeadline - now);
            forgetCallIds();
            callId = owner.newCallId();
            ref = RemoteSpace.settleRef(callId, request.container());
            takeRef = composite ? RemoteSpace.settleRef(RemoteSpace.takeId(callId), request.takesFrom()) : ref;
            owner.waiting(ref, true);
            if (composite) {
                owner.waiting(takeRef, true);
            }
            waitLeft = wait;
            ackHeader = owner.acks().drain();
            in.clear();
            sent = false;
            long serverWait = wait.isInfinite() ? owner.serverMaxWaitMillis
                    : Math.min(wait.millis(), owner.serverMaxWaitMillis);
            answerNanos = TimeUnit.MILLISECONDS.toNanos(serverWait + owner.options.networkAllowanceMillis());
            ioDeadline = now + answerNanos;
        }

        /**
         * The bytes of the request for the chosen connection: a frame or an HTTP request, after the upgrade request
         * on a new connection that is to carry frames.
         */
        private void encode(boolean framedConnection, boolean upgrade) {
            framed = framedConnection;
            awaitingUpgrade = upgrade;
            byte[] body = request.encode(callId, waitLeft, framed && owner.binaryBodies(request.operation()));
            byte[] bytes = framed
                    ? HttpConnection.operationFrame(connectedTo, request.operation(), ackHeader, body, body.length)
                    : owner.requestBytes(request.operation(), ackHeader, body);
            if (upgrade) {
                byte[] head = HttpConnection.upgradeRequest(connectedTo);
                byte[] both = java.util.Arrays.copyOf(head, head.length + bytes.length);
                System.arraycopy(bytes, 0, both, head.length, bytes.length);
                bytes = both;
            }
            out = ByteBuffer.wrap(bytes);
        }

        /** The connection is ready for what this call waits for. I/O thread. */
        void ready(SelectionKey ready) {
            try {
                if (ready.isConnectable()) {
                    channel.finishConnect();
                    ioDeadline = System.nanoTime() + answerNanos;
                    write();
                } else if (ready.isWritable()) {
                    write();
                } else if (ready.isReadable()) {
                    read();
                }
            } catch (IOException e) {
                broken(e);
            }
        }

        private void write() throws IOException {
            channel.write(out);
            if (out.hasRemaining()) {
                key.interestOps(SelectionKey.OP_WRITE);
            } else {
                sent = true;
                key.interestOps(SelectionKey.OP_READ);
            }
        }

        private void read() throws IOException {
            if (!in.hasRemaining()) {
                ByteBuffer bigger = ByteBuffer.allocate(in.capacity() * 2);
                in.flip();
                bigger.put(in);
                in = bigger;
            }
            int read = channel.read(in);
            if (read < 0) {
                throw new EOFException("the server closed the connection");
            }
            if (awaitingUpgrade && !upgraded()) {
                return;
            }
            RawAnswer answer = framed ? RawAnswer.parseFrame(in.array(), in.position())
                    : RawAnswer.parse(in.array(), in.position());
            if (answer == null) {
                return; // not all there yet
            }
            failingSince = 0;
            active.remove(this);
            key.interestOps(0);
            key.attach(null);
            if (answer.close || idle.size() >= MAX_IDLE) {
                closeQuietly(channel);
            } else {
                key.interestOps(SelectionKey.OP_READ); // notices the server closing it while idle
                idle.addFirst(new IdleChannel(channel, connectedTo, framed));
            }
            channel = null;
            answered(answer);
        }

        /**
         * Reads past the answer to the upgrade request: true once the 101 is read (its bytes dropped from the
         * buffer), false while more bytes are needed. A server that did not switch answered the GET, and treats the
         * frame after it as a broken HTTP request: the request never ran, so it goes again over HTTP, and this
         * server is not asked for frames again.
         */
        private boolean upgraded() throws IOException {
            byte[] data = in.array();
            int length = in.position();
            int headEnd = RawAnswer.headEnd(data, length);
            if (headEnd < 0) {
                if (length > 16 * 1024) {
                    throw new IOException("answer head too long");
                }
                return false;
            }
            if (!new String(data, 0, Math.min(headEnd, 13), StandardCharsets.ISO_8859_1).equals("HTTP/1.1 101 ")) {
                owner.framesRefused(connectedTo);
                active.remove(this);
                closeQuietly(channel);
                channel = null;
                owner.acks().requeue(ackHeader);
                ackHeader = null;
                send();
                return false;
            }
            System.arraycopy(data, headEnd + 4, data, 0, length - headEnd - 4);
            in.position(length - headEnd - 4);
            awaitingUpgrade = false;
            return true;
        }

        private void answered(RawAnswer http) {
            Answer answer;
            try {
                answer = Answer.parse(owner.wire, http.body);
            } catch (RuntimeException e) {
                finish(null, new SpaceException("unreadable answer from " + owner.url() + ": " + e.getMessage()));
                return;
            }
            if (answer.error != null) {
                WireError kind = WireError.byKind(answer.error);
                if (kind == WireError.UNAVAILABLE) {
                    // whether it took effect is not known: settle it like a broken connection
                    if (connectedTo != null) {
                        owner.failover(connectedTo, "it could not complete the call: " + answer.message);
                    }
                    cancelOnServer();
                    finish(null, new robotworld.space.SpaceUnavailableException(
                            connectedTo != null ? connectedTo.url() : owner.url(), answer.message, null));
                } else if (kind == WireError.STOPPING || kind == WireError.BUSY) {
                    owner.acks().requeue(ackHeader); // refused as it arrived, its confirmations may be unread
                    ackHeader = null;
                    if (answer.written) {
                        goOnWithTake();
                    } else {
                        retryLater();
                    }
                } else {
                    finish(null, owner.failure(http.status, kind, answer));
                }
            } else if (answer.more) {
                if (answer.written) {
                    goOnWithTake();
                } else if (!timeout.isInfinite() && System.nanoTime() - operationDeadline >= 0) {
                    finish(null, new SpaceTimeoutException("timed out after " + timeout + " on " + request.operation()));
                } else {
                    attempt = 0;
                    send();
                }
            } else {
                if (answer.ack && running()) {
                    owner.acks().add(takeRef);
                }
                finish(answer.entries, null);
            }
        }

        /** The shift of a shift-then-take happened, its take did not (yet): go on with a plain take. */
        private void goOnWithTake() {
            request = take;
            composite = false;
            attempt = 0;
            send();
        }

        /** When this call's connection attempts started failing. */
        private long failingSince;
        /** The server this call's connection goes to. */
        private Endpoint connectedTo;

        private long firstFailure() {
            if (failingSince == 0) {
                failingSince = System.nanoTime();
            }
            return failingSince;
        }

        private void retryLater() {
            long pause = Math.min(250, 5L << Math.min(attempt++, 10));
            try {
                owner.timer().schedule(() -> {
                    try {
                        execute(this::send);
                    } catch (SpaceClosedException e) {
                        finish(null, e);
                    }
                }, pause, TimeUnit.MILLISECONDS);
            } catch (RejectedExecutionException e) {
                finish(null, new SpaceClosedException("the remote space " + owner.url() + " is closed"));
            }
        }

        void checkDeadline(long now) {
            if (channel != null && now - ioDeadline > 0) {
                broken(new SocketTimeoutException(sent ? "no answer in time" : "cannot connect in time"));
            }
        }

        /** The connection broke (or the server is silent). I/O thread. */
        private void broken(IOException e) {
            active.remove(this);
            if (channel != null) {
                closeQuietly(channel);
                channel = null;
            }
            owner.acks().requeue(ackHeader);
            ackHeader = null;
            boolean stale = reused && attempt == 0;
            if (!stale && connectedTo != null) {
                owner.failover(connectedTo, e); // with several servers, the cancel and what follows go to the next
            }
            if (sent) {
                cancelOnServer(); // whatever the lost take removed goes back
            }
            if (reused && attempt++ == 0 && running()) {
                send(); // most likely a keep-alive connection the server had closed while idle
                return;
            }
            if (!sent && running() && System.nanoTime() - firstFailure() < owner.allowanceNanos()) {
                retryLater(); // not connected yet (a burst of connections, a full accept queue): nothing happened
                return;
            }
            // named after the server that failed: after a failover the client's own URL is already the next one
            finish(null, new SpaceUnavailableException(connectedTo != null ? connectedTo.url() : owner.url(),
                    "cannot reach the space server for "
                    + request.operation() + (composite ? " (whether the shift happened is unknown)" : ""), e));
        }

        private void cancelOnServer() {
            String id = takeRef;
            try {
                owner.timer().execute(() -> owner.cancelQuietly(id));
            } catch (RejectedExecutionException closedMeanwhile) {
                // close() cancels what is left
            }
        }

        private void forgetCallIds() {
            if (callId != null) {
                owner.waiting(ref, false);
                owner.waiting(takeRef, false);
            }
        }

        /** Delivers the outcome once. Any thread. */
        void finish(List<Entry> entries, SpaceException failure) {
            synchronized (this) {
                if (state != 0) {
                    return;
                }
                state = 1;
            }
            if (Thread.currentThread() == thread) {
                active.remove(this);
                forgetCallIds();
            }
            try {
                if (failure != null) {
                    done.failed(failure);
                } else {
                    done.completed(entries);
                }
            } catch (RuntimeException e) {
                LOG.log(System.Logger.Level.WARNING, "a completion of a waiting take failed", e);
            }
        }

        /**
         * Withdraws the call: its connection is closed, and the server is asked to undo its take (a shift of a
         * shift-then-take may have happened). Blocks for at most the network allowance.
         */
        @Override
        public boolean cancel() {
            synchronized (this) {
                if (state != 0) {
                    return false;
                }
                state = 2;
            }
            String[] ids = new String[2];
            CountDownLatch stopped = new CountDownLatch(1);
            try {
                execute(() -> {
                    active.remove(this);
                    if (channel != null) {
                        closeQuietly(channel);
                        channel = null;
                    }
                    if (callId != null) {
                        ids[0] = takeRef;
                        forgetCallIds();
                    }
                    stopped.countDown();
                });
                stopped.await(1, TimeUnit.SECONDS);
            } catch (SpaceClosedException alreadyClosed) {
                return true;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            if (ids[0] != null) {
                owner.cancelQuietly(ids[0]); // unanswered, its entries come back when the lease runs out
            }
            return true;
        }
    }

    /** A complete answer, HTTP or frame, parsed from the bytes read so far. */
    record RawAnswer(int status, byte[] body, boolean close) {

        /** Where the head in {@code data[0, length)} ends (its blank line), or -1. */
        static int headEnd(byte[] data, int length) {
            for (int i = 0; i + 3 < length; i++) {
                if (data[i] == '\r' && data[i + 1] == '\n' && data[i + 2] == '\r' && data[i + 3] == '\n') {
                    return i;
                }
            }
            return -1;
        }

        /** The answer frame in {@code data[0, length)}, or null if it is not complete yet. */
        static RawAnswer parseFrame(byte[] data, int length) throws IOException {
            if (length < 7) {
                return null;
            }
            int size = ByteBuffer.wrap(data, 0, 4).getInt();
            if (size < 3 || size > Integer.MAX_VALUE - 64) {
                throw new IOException("not an answer frame (length " + Integer.toUnsignedString(size) + ")");
            }
            if (length - 4 < size) {
                return null;
            }
            if (length - 4 > size) {
                throw new IOException("more bytes than the answer");
            }
            int status = ((data[4] & 0xff) << 8) | (data[5] & 0xff);
            boolean close = (data[6] & Frames.CLOSING) != 0;
            return new RawAnswer(status, java.util.Arrays.copyOfRange(data, 7, length), close);
        }

        /** The HTTP answer in {@code data[0, length)}, or null if it is not complete yet. */
        static RawAnswer parse(byte[] data, int length) throws IOException {
            int headEnd = headEnd(data, length);
            if (headEnd < 0) {
                if (length > 16 * 1024) {
                    throw new IOException("answer head too long");
                }
                return null;
            }
            String[] lines = new String(data, 0, headEnd, StandardCharsets.ISO_8859_1).split("\r\n");
            String[] statusLine = lines[0].split(" ", 3);
            if (statusLine.length < 2 || !statusLine[0].startsWith("HTTP/1.")) {
                throw new IOException("not an HTTP answer: " + lines[0]);
            }
            int status;
            try {
                status = Integer.parseInt(statusLine[1]);
            } catch (NumberFormatException e) {
                throw new IOException("bad status line: " + lines[0]);
            }
            long contentLength = -1;
            boolean close = statusLine[0].equals("HTTP/1.0");
            for (int i = 1; i < lines.length; i++) {
                int colon = lines[i].indexOf(':');
                if (colon <= 0) {
                    continue;
                }
                String name = lines[i].substring(0, colon).trim().toLowerCase(Locale.ROOT);
                String value = lines[i].substring(colon + 1).trim();
                switch (name) {
                    case "content-length" -> contentLength = Long.parseLong(value);
                    case "transfer-encoding" -> throw new IOException("a chunked answer to a waiting take");
                    case "connection" -> close = value.equalsIgnoreCase("close");
                    default -> { }
                }
            }
            if (contentLength < 0 || contentLength > Integer.MAX_VALUE - 64) {
                throw new IOException("answer without a usable length");
            }
            int bodyStart = headEnd + 4;
            if (length - bodyStart < contentLength) {
                return null;
            }
            if (length - bodyStart > contentLength) {
                throw new IOException("more bytes than the answer");
            }
            byte[] body = new byte[(int) contentLength];
            System.arraycopy(data, bodyStart, body, 0, body.length);
            return new RawAnswer(status, body, close);
        }
    }
}
