package robotworld.space.server;

import java.util.concurrent.CompletionException;

import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.io.Content;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.Promise;
import org.eclipse.jetty.util.thread.Invocable;

import robotworld.space.wire.Wire;
import robotworld.space.wire.WireError;

/**
 * {@code POST <path>/<operation>}: runs one operation of the wire protocol, as a Jetty core handler that never
 * blocks. The request is answered on the thread that completes it: at once for an operation that can happen at
 * once, otherwise by whoever makes it possible (a write or shift on another request's thread, the space's timer,
 * a cancel). An engine whose calls may block (a cluster's cross the network) gets each request on a pool thread
 * instead. The request's body has already arrived when this runs (an {@code EagerContentHandler} in front), so a
 * slow sender holds no thread. Because nothing here blocks, Jetty runs it on the thread that read the request,
 * without a hand-off; the other requests ({@code GET <path>}, {@code GET <path>/health}, the notification streams)
 * go to the servlet on a pool thread.
 *
 * <p>Every request is authenticated (when a token is set), size-checked, and parsed strictly; every failure is a
 * JSON error answer with a 4xx or 5xx status. See {@code docs/wire.md}.
 */
final class OperationsHandler extends Handler.Wrapper {

    private final ServerState state;
    private final SpaceOperations operations;
    private final String prefix;
    private final String eventsPath;
    private final String healthPath;

    OperationsHandler(ServerState state, Handler servlets) {
        super(servlets);
        this.state = state;
        this.operations = new SpaceOperations(state);
        this.prefix = state.options.path() + "/";
        this.eventsPath = state.options.path() + "/events";
        this.healthPath = state.options.path() + "/health";
    }

    @Override
    public Invocable.InvocationType getInvocationType() {
        return Invocable.InvocationType.NON_BLOCKING; // the servlet's requests are handed to a pool thread below
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        String refused = state.clients.arrived(request);
        if (refused != null) {
            HttpExchange exchange = new HttpExchange(response, callback, state.wire, null);
            exchange.header(HttpHeader.CONNECTION, "close");
            exchange.fail(WireError.BUSY, refused, false);
            return true;
        }
        String path = request.getHttpURI().getPath();
        if (path == null || !path.startsWith(prefix) || path.equals(eventsPath) || path.equals(healthPath)
                || path.length() == prefix.length()) {
            // the servlet may block (the notification stream does): never on this thread
            getServer().getThreadPool().execute(() -> {
                try {
                    if (!super.handle(request, response, callback)) {
                        Response.writeError(request, response, callback, 404);
                    }
                } catch (Throwable e) {
                    Response.writeError(request, response, callback, e);
                }
            });
            return true;
        }
        if (state.space.callsMayBlock()) {
            // an engine whose calls cross the network (a cluster): never block the thread that reads requests
            getServer().getThreadPool().execute(() -> operate(path, request, response, callback));
        } else {
            operate(path, request, response, callback);
        }
        return true;
    }

    /** Runs one operation request; answers it (at once, or later from the thread that completes it). */
    private void operate(String path, Request request, Response response, Callback callback) {
        HttpExchange exchange = new HttpExchange(response, callback, state.wire,
                state.clients.waitingClient(request));
        try {
            if (state.token != null && !state.token.accepts(request.getHeaders().get(HttpHeader.AUTHORIZATION))) {
                exchange.header(HttpHeader.WWW_AUTHENTICATE, "Bearer realm=\"space\"");
                throw new ErrorAnswer(WireError.UNAUTHORIZED, "this space needs 'Authorization: Bearer <token>'");
            }
            if (!"POST".equals(request.getMethod())) {
                exchange.header(HttpHeader.ALLOW, "POST");
                throw new ErrorAnswer(WireError.METHOD_NOT_ALLOWED, "use POST here, not "
                        + Exchange.truncate(request.getMethod(), 40));
            }
            if (!isJson(request.getHeaders().get(HttpHeader.CONTENT_TYPE))) {
                throw new ErrorAnswer(WireError.UNSUPPORTED_MEDIA_TYPE, "send the body as " + Wire.MEDIA_TYPE);
            }
            int max = state.wire.limits().maxBodyBytes();
            long declared = request.getLength();
            if (declared > max) {
                throw new ErrorAnswer(WireError.TOO_LARGE, "the body has " + declared + " bytes; at most " + max);
            }
            String name = path.substring(prefix.length());
            String acks = request.getHeaders().get(Wire.ACK_HEADER);
            // the body is all there already, so this completes at once, on this thread
            Content.Source.asByteArrayAsync(request, max + 1, Promise.Invocable.from(Invocable.InvocationType.NON_BLOCKING,
                    (byte[] body, Throwable failure) -> {
                try {
                    if (failure != null) {
                        Throwable cause = failure instanceof CompletionException ? failure.getCause() : failure;
                        throw cause instanceof IllegalArgumentException || cause instanceof IllegalStateException
                                ? new ErrorAnswer(WireError.TOO_LARGE, "the body has more than " + max + " bytes")
                                : new ErrorAnswer(WireError.BAD_REQUEST, "the body could not be read: " + cause);
                    }
                    if (body.length > max) {
                        throw new ErrorAnswer(WireError.TOO_LARGE, "the body has more than " + max + " bytes");
                    }
                    if (declared >= 0 && body.length < declared) {
                        throw new ErrorAnswer(WireError.BAD_REQUEST, "the body is shorter than its Content-Length");
                    }
                    operations.perform(name, body, acks, exchange);
                } catch (RuntimeException e) {
                    exchange.fail(e);
                }
            }));
        } catch (RuntimeException e) {
            exchange.fail(e);
        }
    }

    private static boolean isJson(String contentType) {
        if (contentType == null) {
            return false;
        }
        int semicolon = contentType.indexOf(';');
        String type = (semicolon < 0 ? contentType : contentType.substring(0, semicolon)).trim();
        return type.equalsIgnoreCase(Wire.MEDIA_TYPE);
    }
}
