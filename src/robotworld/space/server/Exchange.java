package robotworld.space.server;

import java.io.ByteArrayOutputStream;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.lang.System.Logger.Level;
import java.nio.ByteBuffer;
import java.util.concurrent.atomic.AtomicBoolean;

import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;

import robotworld.space.wire.Wire;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireError;
import robotworld.space.wire.WireFormatException;
import robotworld.space.wire.WireWriter;

/**
 * One operation request and its answer. The answer may be sent from any thread: the request's own, or, for an
 * operation that waited, whichever thread completed it (the one that wrote the awaited entry, the space's timer,
 * a cancel). Sending never blocks: the bytes are handed to Jetty, which writes them when the connection can take
 * them. The first answer wins; later ones are ignored.
 */
final class Exchange {

    private static final System.Logger LOG = System.getLogger(Exchange.class.getName());
    private static final int MAX_MESSAGE_CHARS = 300;

    private final Response response;
    private final Callback callback;
    private final WireContext wire;
    private final AtomicBoolean answered = new AtomicBoolean();
    /** The address whose waiting places this request uses, or null (a request with the token). */
    private final InetAddress client;

    Exchange(Response response, Callback callback, WireContext wire, InetAddress client) {
        this.response = response;
        this.callback = callback;
        this.wire = wire;
        this.client = client;
    }

    /** The address whose waiting places this request uses, or null if it is not limited per address. */
    InetAddress client() {
        return client;
    }

    /** A new answer body, its object already opened. */
    Body body() {
        return new Body(wire);
    }

    /** Closes the object of {@code body} and sends it with status 200. */
    void answer(Body body) {
        body.out.endObject();
        body.out.close();
        send(200, body.bytes);
    }

    /** Adds a header to the answer (before it is sent). */
    void header(HttpHeader name, String value) {
        response.getHeaders().put(name, value);
    }

    /** Answers with the error that {@code failure} stands for. */
    void fail(RuntimeException failure) {
        if (failure instanceof ErrorAnswer e) {
            fail(e.error, e.getMessage(), e.written);
        } else if (failure instanceof WireFormatException e) {
            fail(WireError.BAD_REQUEST, e.getMessage(), false);
        } else if (failure instanceof UncheckedIOException e) {
            if (answered.compareAndSet(false, true)) {
                callback.failed(e.getCause());
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
        if (kind == WireError.BUSY || kind == WireError.STOPPING) {
            response.getHeaders().put(HttpHeader.RETRY_AFTER, "1");
        }
        send(kind.status(), bytes);
    }

    private void send(int status, ByteArrayOutputStream body) {
        if (!answered.compareAndSet(false, true)) {
            return;
        }
        try {
            response.setStatus(status);
            response.getHeaders().put(HttpHeader.CONTENT_TYPE, Wire.MEDIA_TYPE);
            response.getHeaders().put(HttpHeader.CONTENT_LENGTH, body.size());
            // the client may be gone: an unconfirmed take then comes back when its lease runs out
            ByteBuffer bytes = ByteBuffer.wrap(body.toByteArray());
            // once written, the connection reads on here rather than on a woken pool thread
            ResumeInPlace.answering(() -> response.write(true, bytes, callback));
        } catch (RuntimeException e) {
            LOG.log(Level.DEBUG, "cannot answer a space request: " + e);
            callback.failed(e);
        }
    }

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

        Body(WireContext wire) {
            out = wire.writer(bytes);
            out.startObject();
        }
    }
}
