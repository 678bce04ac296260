package robotworld.space.server;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeoutException;

import org.eclipse.jetty.io.AbstractConnection;
import org.eclipse.jetty.io.Connection;
import org.eclipse.jetty.io.EndPoint;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.thread.Invocable;

import robotworld.space.wire.Frames;
import robotworld.space.wire.WireError;

/**
 * A connection carrying operation requests as frames ({@link Frames}): reads one request, runs it as
 * {@link OperationsHandler} runs an HTTP one (token, limits, the same operations), and reads the next once the
 * answer is written. Nothing here blocks: Jetty calls {@link #onFillable} on the selector thread, an operation that
 * can happen at once is answered there, and one that waits is answered from the thread that completes it, which
 * then reads on (the client's next request is usually not there yet, and the connection waits for it without a
 * thread). With an engine whose calls may block (a cluster) each request runs on a pool thread.
 *
 * <p>At most one request is in hand: the next is read once the answer to the last is written. One thread at a time
 * reads the buffer ({@link #readOn}); an answer written while a thread reads (the dispatching one, say) leaves it a
 * note to read on, which keeps the stack flat however many requests a client sends back to back. While a request is
 * in hand the connection stays registered for reading, so a client that closes it is noticed at once, and an
 * answer sent from another selector's thread does not have to wake this connection's selector to register it again
 * (that wake-up held the JDK selector's wake-up lock, which showed as stalls of the selector threads).
 */
final class FrameConnection extends AbstractConnection.NonBlocking implements Connection.UpgradeTo {

    private static final System.Logger LOG = System.getLogger(FrameConnection.class.getName());
    private static final int INITIAL_BUFFER = 4096;

    private final ServerState state;
    private final SpaceOperations operations;
    private final int maxFrame;
    private ByteBuffer in = ByteBuffer.allocate(INITIAL_BUFFER).flip(); // flush mode: position..limit unread
    /** Guarded by this: a thread is reading (see {@link #readOn}). */
    private boolean reading;
    /** Guarded by this: something happened while a thread was reading, which it looks at before it stops. */
    private boolean readAgain;
    /** A request is in hand (not yet answered): the connection is not idle then, whatever its timeout says. */
    private volatile boolean inHand;
    private volatile long bytesIn;
    private volatile long bytesOut;
    private volatile long messagesIn;
    private volatile long messagesOut;

    FrameConnection(EndPoint endPoint, Executor executor, ServerState state) {
        super(endPoint, executor);
        this.state = state;
        this.operations = new SpaceOperations(state);
        this.maxFrame = state.wire.limits().maxBodyBytes() + Frames.MAX_REQUEST_OVERHEAD;
    }

    @Override
    public void onUpgradeTo(ByteBuffer buffer) {
        // bytes that came after the upgrade request, if the client did not wait for its answer
        if (buffer != null && buffer.hasRemaining()) {
            in = ByteBuffer.allocate(Math.max(INITIAL_BUFFER, buffer.remaining())).put(buffer).flip();
            bytesIn += in.remaining();
        }
    }

    @Override
    public void onOpen() {
        super.onOpen();
        enterRound();
        readOn();
    }

    @Override
    public void onFillable() {
        enterRound();
        readOn();
    }

    /** Answers this thread writes from here to the end of its selector's round go out together (AnswerRound). */
    private void enterRound() {
        if (getEndPoint() instanceof ClosingConnector.RoundEndPoint endPoint && endPoint.round != null) {
            endPoint.round.enter();
        }
    }

    @Override
    public boolean onIdleExpired(TimeoutException timeout) {
        return !inHand && super.onIdleExpired(timeout); // a waiting operation is answered before its bound anyway
    }

    /**
     * Reads until a request is in hand (and dispatches it) or no bytes are left; then waits for more without a thread.
     * One thread at a time: one that comes while another reads (an answer written meanwhile, bytes arriving) leaves
     * it a note to go round once more.
     */
    private void readOn() {
        synchronized (this) {
            if (reading) {
                readAgain = true;
                return;
            }
            reading = true;
        }
        while (true) {
            readWhatIsThere();
            synchronized (this) {
                if (!readAgain) {
                    reading = false;
                    return;
                }
                readAgain = false;
            }
        }
    }

    /**
     * Dispatches the whole requests in the buffer and reads on. While a request is in hand the connection stays
     * registered for reading: the client sends nothing then, so what wakes it is the client closing the connection
     * (noticed at once, not when the answer finds it gone), and the answer, sent from whichever thread completes
     * the operation, finds reading already armed and need not wake this connection's selector to arm it. Bytes that
     * come while a request is in hand wait in the buffer until its answer is written.
     */
    private void readWhatIsThere() {
        try {
            while (true) {
                if (!inHand) {
                    Request request = nextRequest();
                    if (request == Request.BROKEN) {
                        return; // answered with an error; the connection closes after it
                    }
                    if (request != null) {
                        dispatch(request);
                        if (inHand) {
                            armReading(); // its answer will come from another thread
                            return;
                        }
                        continue;
                    }
                }
                if (!in.hasRemaining() || in.limit() == in.capacity()) {
                    compactOrGrow();
                    if (inHand && in.limit() == in.capacity()) {
                        return; // full while a request is in hand: read on once it is answered
                    }
                }
                int read = getEndPoint().fill(in);
                if (read < 0) {
                    getEndPoint().shutdownOutput();
                    close();
                    return;
                }
                if (read == 0) {
                    armReading();
                    return;
                }
                bytesIn += read;
                if (inHand) {
                    return; // sent before the answer: kept until the answer is written, which reads on
                }
            }
        } catch (IOException e) {
            close(); // the socket failed (reset by the client, say): nothing to answer
        } catch (RuntimeException | Error e) {
            LOG.log(System.Logger.Level.WARNING, "a framed connection failed; closing it", e);
            close();
        }
    }

    /**
     * After an answer written at the end of its selector's round: true if reading on can wait for the selector's
     * next {@code select()}, which then finds the client's next request with those of every other client answered
     * in the round. Read on at once, a client that ran the moment its answer woke it (taking the CPU from the
     * selector thread, which then wrote the round's other answers later) had its next request served within the
     * same round, again and again, while the others waited a round: with 50 busy pairs, about half of all requests
     * went that way, and the pairs that got them made up to three times the calls of the others.
     *
     * <p>Safe because, while no thread is reading this connection and no bytes wait in its buffer, reading is armed
     * (or Jetty is about to call {@link #onFillable}): a request in hand keeps it armed. Bytes already buffered
     * (sent before the answer) are read on at once, as is a connection another thread is reading.
     */
    private boolean waitsForNextRound() {
        synchronized (this) {
            return !reading && !in.hasRemaining();
        }
    }

    /** Registers for reading unless already registered (an answer may come while reading is armed). */
    private void armReading() {
        if (!isFillInterested()) {
            fillInterested();
        }
    }

    /** Hands a request to its operation; its answer may be written before this returns. */
    private void dispatch(Request request) {
        messagesIn++;
        inHand = true;
        boolean withToken = state.token != null && request.token != null && state.token.acceptsToken(request.token);
        FrameExchange exchange = new FrameExchange(this, state.wire,
                state.clients.waitingClient(getEndPoint().getRemoteSocketAddress(), withToken));
        String refused = state.clients.arrived(this, withToken);
        if (refused != null) {
            exchange.closing = true;
            exchange.fail(WireError.BUSY, refused, false);
        } else if (state.token != null && !withToken) {
            exchange.fail(WireError.UNAUTHORIZED, "this space needs its access token", false);
        } else if (state.space.callsMayBlock()) {
            // an engine whose calls cross the network (a cluster): never block the thread that reads requests
            getExecutor().execute(() -> perform(request, exchange));
        } else {
            perform(request, exchange);
        }
    }

    private void perform(Request request, FrameExchange exchange) {
        try {
            operations.perform(request.name, request.body, request.acks, exchange);
        } catch (RuntimeException e) {
            exchange.fail(e);
        }
    }

    /** Sends an answer frame (from any thread, once per request); reading goes on when it is written. */
    void answer(int status, byte[] body, int flags) {
        ByteBuffer frame = ByteBuffer.allocate(4 + 3 + body.length);
        frame.putInt(3 + body.length).putShort((short) status).put((byte) flags).put(body).flip();
        boolean closing = (flags & Frames.CLOSING) != 0;
        Written written = new Written(frame.remaining(), closing);
        EndPoint endPoint = getEndPoint();
        AnswerRound.write(() -> endPoint.write(written, frame));
    }

    /** The answer could not be sent: the connection is given up (the client sees it closed). */
    void abandon() {
        inHand = false;
        close();
    }

    /** What comes after an answer is written: read on, or close. */
    private final class Written implements Callback {
        private final int bytes;
        private final boolean closing;

        Written(int bytes, boolean closing) {
            this.bytes = bytes;
            this.closing = closing;
        }

        @Override
        public void succeeded() {
            bytesOut += bytes;
            messagesOut++;
            inHand = false;
            if (closing) {
                getEndPoint().shutdownOutput();
                close();
                return;
            }
            if (AnswerRound.atRoundEnd() && waitsForNextRound()) {
                return;
            }
            readOn();
        }

        @Override
        public void failed(Throwable cause) {
            abandon();
        }

        @Override
        public Invocable.InvocationType getInvocationType() {
            return Invocable.InvocationType.NON_BLOCKING; // reading on never blocks
        }
    }

    // ---- parsing ----

    /** One request frame's fields. */
    private record Request(String name, String token, String acks, byte[] body) {
        static final Request BROKEN = new Request(null, null, null, null);
    }

    /** The next whole request in the buffer; null if more bytes are needed; {@link Request#BROKEN} after an error. */
    private Request nextRequest() {
        if (in.remaining() < 4) {
            return null;
        }
        int length = in.getInt(in.position());
        if (length > maxFrame || length < 0) {
            return broken(WireError.TOO_LARGE, "a request frame has " + Integer.toUnsignedString(length)
                    + " bytes; at most " + maxFrame);
        }
        if (in.remaining() < 4 + length) {
            return null;
        }
        int end = in.position() + 4 + length;
        ByteBuffer frame = in.duplicate().position(in.position() + 4).limit(end);
        in.position(end);
        String name = text(frame, frame.hasRemaining() ? Byte.toUnsignedInt(frame.get()) : -1);
        String token = frame.remaining() >= 2 ? utf8(frame, Short.toUnsignedInt(frame.getShort())) : null;
        String acks = frame.remaining() >= 2 ? text(frame, Short.toUnsignedInt(frame.getShort())) : null;
        if (name == null || token == null || acks == null || name.isEmpty()) {
            return broken(WireError.BAD_REQUEST, "a request frame is shorter than its fields say");
        }
        byte[] body = new byte[frame.remaining()];
        frame.get(body);
        return new Request(name, token.isEmpty() ? null : token, acks.isEmpty() ? null : acks, body);
    }

    /** {@code length} bytes of ASCII text, or null if the frame does not have them or they are not printable. */
    private static String text(ByteBuffer frame, int length) {
        if (length < 0 || frame.remaining() < length) {
            return null;
        }
        byte[] bytes = new byte[length];
        frame.get(bytes);
        for (byte b : bytes) {
            if (b < 0x21 || b > 0x7e) {
                return null;
            }
        }
        return new String(bytes, StandardCharsets.US_ASCII);
    }

    /** {@code length} bytes of UTF-8 text, or null if the frame does not have them. */
    private static String utf8(ByteBuffer frame, int length) {
        if (frame.remaining() < length) {
            return null;
        }
        byte[] bytes = new byte[length];
        frame.get(bytes);
        return new String(bytes, StandardCharsets.UTF_8);
    }

    /** Answers a frame that cannot be read with an error, then closes: where the next frame starts is unknown. */
    private Request broken(WireError kind, String message) {
        inHand = true;
        FrameExchange exchange = new FrameExchange(this, state.wire, null);
        exchange.closing = true;
        exchange.fail(kind, message, false);
        return Request.BROKEN;
    }

    private void compactOrGrow() {
        if (in.position() > 0) {
            in.compact().flip();
        }
        if (in.limit() == in.capacity()) {
            int wanted = in.remaining() >= 4 ? Math.min(maxFrame, in.getInt(in.position())) + 4 : INITIAL_BUFFER;
            int capacity = Math.max(in.capacity() * 2, wanted);
            in = ByteBuffer.allocate(Math.min(capacity, maxFrame + 4)).put(in).flip();
        }
    }

    @Override
    public long getBytesIn() {
        return bytesIn;
    }

    @Override
    public long getBytesOut() {
        return bytesOut;
    }

    @Override
    public long getMessagesIn() {
        return messagesIn;
    }

    @Override
    public long getMessagesOut() {
        return messagesOut;
    }
}
