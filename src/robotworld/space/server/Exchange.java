package robotworld.space.server;

import java.io.ByteArrayOutputStream;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.lang.System.Logger.Level;
import java.util.concurrent.atomic.AtomicBoolean;

import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireError;
import robotworld.space.wire.WireFormatException;
import robotworld.space.wire.WireWriter;

/**
 * One operation request and its answer, whatever carried it (an HTTP request, {@link HttpExchange}, or a frame,
 * {@link FrameExchange}). The answer may be sent from any thread: the request's own, or, for an operation that
 * waited, whichever thread completed it (the one that wrote the awaited entry, the space's timer, a cancel).
 * Sending never blocks: the bytes are handed to Jetty, which writes them when the connection can take them. The
 * first answer wins; later ones are ignored.
 */
abstract class Exchange {

    private static final System.Logger LOG = System.getLogger(Exchange.class.getName());
    private static final int MAX_MESSAGE_CHARS = 300;

    private final WireContext wire;
    private final AtomicBoolean answered = new AtomicBoolean();
    private boolean binary;
    /** The address whose waiting places this request uses, or null (a request with the token). */
    private final InetAddress client;

    Exchange(WireContext wire, InetAddress client) {
        this.wire = wire;
        this.client = client;
    }

    /** The address whose waiting places this request uses, or null if it is not limited per address. */
    InetAddress client() {
        return client;
    }

    /** A new answer body, its object already opened. */
    Body body() {
        return new Body(wire, binary);
    }

    /** The request came in the binary form: so does a successful answer (errors stay JSON). */
    void answerInBinary() {
        binary = true;
    }

    /** Closes the object of {@code body} and sends it with status 200. */
    void answer(Body body) {
        body.out.endObject();
        body.out.close();
        send(200, body.bytes, false);
    }

    /** Answers with the error that {@code failure} stands for. */
    void fail(RuntimeException failure) {
        if (failure instanceof ErrorAnswer e) {
            fail(e.error, e.getMessage(), e.written);
        } else if (failure instanceof WireFormatException e) {
            fail(WireError.BAD_REQUEST, e.getMessage(), false);
        } else if (failure instanceof UncheckedIOException e) {
            if (answered.compareAndSet(false, true)) {
                abandon(e.getCause());
            }
        } else {
            WireError kind = WireError.of(failure);
            if (kind == WireError.INTERNAL) {
                LOG.log(Level.WARNING, "space request failed", failure);
            }
            fail(kind, failure.getMessage() == null ? failure.toString() : failure.getMessage(), false);
        }
    }

    /** Answers with an error body; {@code written} says that the write of a write-then-take happened. */
    void fail(WireError kind, String message, boolean written) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(128);
        try (WireWriter out = wire.writer(bytes)) {
            out.startObject().field("error", kind.kind()).field("message", truncate(message, MAX_MESSAGE_CHARS));
            if (written) {
                out.field("written", true);
            }
            out.endObject();
        }
        send(kind.status(), bytes, kind == WireError.BUSY || kind == WireError.STOPPING);
    }

    private void send(int status, ByteArrayOutputStream body, boolean retryLater) {
        if (!answered.compareAndSet(false, true)) {
            return;
        }
        // the client may be gone: an unconfirmed take then comes back when its lease runs out
        try {
            transmit(status, body.toByteArray(), retryLater);
        } catch (RuntimeException e) {
            LOG.log(Level.DEBUG, "cannot answer a space request: " + e);
            abandon(e);
        }
    }

    /**
     * Hands the answer to the connection, without blocking (called once).
     *
     * @param retryLater the client should wait a second before asking again (busy, stopping)
     */
    abstract void transmit(int status, byte[] body, boolean retryLater);

    /** The answer cannot be sent: the connection is given up (called at most once, instead of transmit). */
    abstract void abandon(Throwable cause);

    static String truncate(String text, int max) {
        if (text == null) {
            return "";
        }
        return text.length() <= max ? text : text.substring(0, max) + "...";
    }

    /** An answer body being written: fields go to {@link #out}. */
    static final class Body {
        final ByteArrayOutputStream bytes = new ByteArrayOutputStream(128);
        final WireWriter out;

        Body(WireContext wire, boolean binary) {
            out = binary ? WireWriter.binary(wire.crefs(), bytes) : wire.writer(bytes);
            out.startObject();
        }
    }
}
