package robotworld.space.server;

import java.net.InetAddress;
import java.nio.ByteBuffer;

import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;

import robotworld.space.wire.Wire;
import robotworld.space.wire.WireContext;

/** An operation that came as an HTTP request ({@code POST <path>/<operation>}), answered as its response. */
final class HttpExchange extends Exchange {

    private final Response response;
    private final Callback callback;

    HttpExchange(Response response, Callback callback, WireContext wire, InetAddress client) {
        super(wire, client);
        this.response = response;
        this.callback = callback;
    }

    /** Adds a header to the answer (before it is sent). */
    void header(HttpHeader name, String value) {
        response.getHeaders().put(name, value);
    }

    @Override
    void transmit(int status, byte[] body, boolean retryLater) {
        response.setStatus(status);
        response.getHeaders().put(HttpHeader.CONTENT_TYPE, Wire.MEDIA_TYPE);
        response.getHeaders().put(HttpHeader.CONTENT_LENGTH, body.length);
        if (retryLater) {
            response.getHeaders().put(HttpHeader.RETRY_AFTER, "1");
        }
        // once written, the connection reads on here rather than on a woken pool thread
        ResumeInPlace.answering(() -> response.write(true, ByteBuffer.wrap(body), callback));
    }

    @Override
    void abandon(Throwable cause) {
        callback.failed(cause);
    }
}
