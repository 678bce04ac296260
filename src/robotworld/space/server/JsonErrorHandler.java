package robotworld.space.server;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;

import org.eclipse.jetty.http.HttpFields;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.handler.ErrorHandler;
import org.eclipse.jetty.util.Callback;

import robotworld.space.wire.Wire;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireError;
import robotworld.space.wire.WireWriter;

/**
 * Errors Jetty answers itself, before a request reaches the space (a malformed request line, headers too large,
 * an unsupported HTTP version, an HTTP/2 preface (426), a body that ends early), whatever the request's method:
 * the same JSON error body as every other failure,
 * {@code {"error": kind, "message": text}}, with Jetty's status, instead of Jetty's HTML page.
 */
final class JsonErrorHandler extends ErrorHandler {

    private static final int MAX_MESSAGE_CHARS = 300;

    private final WireContext wire;

    JsonErrorHandler(WireContext wire) {
        this.wire = wire;
    }

    /** Every method gets its error body (Jetty's default writes none for others than GET, POST and HEAD). */
    @Override
    public boolean errorPageForMethod(String method) {
        return true;
    }

    @Override
    protected void generateResponse(Request request, Response response, int code, String message, Throwable cause,
                                    Callback callback) throws IOException {
        response.getHeaders().put(HttpHeader.CONTENT_TYPE, Wire.MEDIA_TYPE);
        response.write(true, ByteBuffer.wrap(body(code, message)), callback);
    }

    /** A request Jetty could not parse at all: it answers with this body and closes the connection. */
    @Override
    public ByteBuffer badMessageError(int status, String reason, HttpFields.Mutable fields) {
        fields.put(HttpHeader.CONTENT_TYPE, Wire.MEDIA_TYPE);
        return ByteBuffer.wrap(body(status, reason));
    }

    private byte[] body(int status, String reason) {
        ByteArrayOutputStream body = new ByteArrayOutputStream(128);
        String message = reason == null || reason.isBlank() ? "HTTP status " + status : reason;
        try (WireWriter out = wire.writer(body)) {
            out.startObject().field("error", kindOf(status).kind())
                    .field("message", message.length() <= MAX_MESSAGE_CHARS ? message
                            : message.substring(0, MAX_MESSAGE_CHARS) + "...")
                    .endObject();
        }
        return body.toByteArray();
    }

    /** The wire's error kind for a status Jetty chose. */
    static WireError kindOf(int status) {
        return switch (status) {
            case 401 -> WireError.UNAUTHORIZED;
            case 404 -> WireError.NO_SUCH_ENDPOINT;
            case 405 -> WireError.METHOD_NOT_ALLOWED;
            case 413, 414, 431 -> WireError.TOO_LARGE;
            case 415 -> WireError.UNSUPPORTED_MEDIA_TYPE;
            case 503 -> WireError.BUSY;
            default -> status >= 500 && status != 505 ? WireError.INTERNAL : WireError.BAD_REQUEST;
        };
    }
}
