package robotworld.space.server;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.lang.System.Logger.Level;
import java.nio.charset.StandardCharsets;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

import jakarta.servlet.http.HttpServlet;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

import robotworld.space.ClusterHealth;
import robotworld.space.wire.BinaryWire;
import robotworld.space.wire.Wire;
import robotworld.space.wire.WireError;
import robotworld.space.wire.WireFormatException;
import robotworld.space.wire.WireReader;
import robotworld.space.wire.WireWriter;

/**
 * The HTTP face of a space besides its operations ({@link OperationsHandler}): {@code GET <path>} describes the
 * server, {@code GET <path>/events?session=ID} streams notifications (one thread per stream, bounded by the
 * number of sessions). Every request is authenticated (when a token is set); every failure is a JSON error answer
 * with a 4xx or 5xx status. See {@code docs/wire.md}.
 */
final class SpaceServlet extends HttpServlet {

    private static final System.Logger LOG = System.getLogger(SpaceServlet.class.getName());
    private static final int MAX_MESSAGE_CHARS = 300;

    private final transient ServerState state;

    SpaceServlet(ServerState state) {
        this.state = state;
    }

    @Override
    protected void service(HttpServletRequest request, HttpServletResponse response) throws IOException {
        try {
            if (state.token != null && !state.token.accepts(request.getHeader("Authorization"))) {
                response.setHeader("WWW-Authenticate", "Bearer realm=\"space\"");
                throw new ErrorAnswer(WireError.UNAUTHORIZED, "this space needs 'Authorization: Bearer <token>'");
            }
            String path = request.getPathInfo();
            if (path == null || path.equals("/")) {
                requireMethod(request, response, "GET");
                hello(response);
            } else if (path.equals("/health")) {
                requireMethod(request, response, "GET");
                health(response);
            } else if (path.equals("/events")) {
                requireMethod(request, response, "GET");
                events(request, response);
            } else {
                throw new ErrorAnswer(WireError.NO_SUCH_ENDPOINT, "no such path"); // operations: OperationsHandler
            }
        } catch (ErrorAnswer e) {
            error(response, e.error, e.getMessage(), e.written);
        } catch (WireFormatException e) {
            error(response, WireError.BAD_REQUEST, e.getMessage(), false);
        } catch (UncheckedIOException e) {
            throw e.getCause(); // the connection failed: nobody to answer
        } catch (RuntimeException e) {
            WireError kind = WireError.of(e);
            if (kind == WireError.INTERNAL) {
                LOG.log(Level.WARNING, "space request failed", e);
            }
            error(response, kind, e.getMessage() == null ? e.toString() : e.getMessage(), false);
        }
    }

    private static void requireMethod(HttpServletRequest request, HttpServletResponse response, String method) {
        if (!method.equals(request.getMethod())) {
            response.setHeader("Allow", method);
            throw new ErrorAnswer(WireError.METHOD_NOT_ALLOWED, "use " + method + " here, not "
                    + truncate(request.getMethod()));
        }
    }

    // ---- GET <path> ----

    private void hello(HttpServletResponse response) throws IOException {
        ByteArrayOutputStream body = new ByteArrayOutputStream(256);
        try (WireWriter out = state.wire.writer(body)) {
            out.startObject()
                    .field("space", state.crefUri.toString())
                    .field("maxWait", state.options.maxWaitMillis())
                    .field("heartbeat", state.options.heartbeatMillis())
                    .field("lease", state.options.leaseMillis())
                    .field("maxBodyBytes", state.wire.limits().maxBodyBytes())
                    .field("maxDepth", state.wire.limits().maxDepth())
                    .field("maxCount", state.wire.limits().maxCount())
                    .field("frames", 1) // the frame version this server also speaks on its port
                    .field("binary", BinaryWire.VERSION) // and the binary form of bodies it reads in frames
                    .endObject();
        }
        send(response, 200, body);
    }

    // ---- GET <path>/health ----

    /**
     * For operators: the space this server serves and, for a cluster, how its member sees it. Apart from the
     * description above, since asking the cluster whether every backup is in place can take a while (it asks every
     * member), and clients describe the server whenever they connect.
     */
    private void health(HttpServletResponse response) throws IOException {
        ByteArrayOutputStream body = new ByteArrayOutputStream(128);
        try (WireWriter out = state.wire.writer(body)) {
            out.startObject().field("space", state.crefUri.toString());
            Optional<ClusterHealth> cluster = state.space.clusterHealth();
            if (cluster.isPresent()) { // only a clustered space has members to count
                out.field("cluster").startObject()
                        .field("members", cluster.get().members())
                        .field("backupsInPlace", cluster.get().backupsInPlace())
                        .endObject();
            }
            out.endObject();
        }
        send(response, 200, body);
    }

    // ---- GET <path>/events ----

    private void events(HttpServletRequest request, HttpServletResponse response) throws IOException {
        String id = request.getParameter("session");
        if (id == null) {
            throw new ErrorAnswer(WireError.BAD_REQUEST, "the stream needs ?session=<id>");
        }
        RequestFields.id(id, "session");
        long after = -1;
        String afterParameter = request.getParameter("after");
        if (afterParameter != null) {
            try {
                after = Long.parseLong(afterParameter);
            } catch (NumberFormatException e) {
                throw new ErrorAnswer(WireError.BAD_REQUEST, "'after' must be a frame number");
            }
        }
        if (state.stopping) {
            throw new ErrorAnswer(WireError.STOPPING, "the server is stopping");
        }
        SessionRegistry.Opened opened;
        try {
            opened = state.sessions.open(id, after);
        } catch (IllegalStateException full) {
            throw new ErrorAnswer(WireError.BUSY, full.getMessage());
        }
        EventSession session = opened.session();
        long generation = opened.attachment().generation();
        try {
            response.setStatus(200);
            response.setContentType(Wire.STREAM_MEDIA_TYPE);
            response.setHeader("Cache-Control", "no-store");
            OutputStream out = response.getOutputStream();
            out.write(("{\"session\":\"" + id + "\",\"heartbeat\":" + state.options.heartbeatMillis()
                    + ",\"resumed\":" + opened.resumed() + "}\n").getBytes(StandardCharsets.US_ASCII));
            for (EventSession.Frame frame : opened.attachment().replay()) {
                out.write(frame.bytes()); // frames the previous stream may have lost
            }
            out.flush();
            stream(session, generation, out);
        } finally {
            session.detached(generation);
        }
    }

    private void stream(EventSession session, long generation, OutputStream out) throws IOException {
        long heartbeat = TimeUnit.MILLISECONDS.toNanos(state.options.heartbeatMillis());
        byte[] beat = "{\"hb\":1}\n".getBytes(StandardCharsets.US_ASCII);
        while (true) {
            EventSession.Frame frame;
            try {
                frame = session.next(generation, heartbeat);
                if (frame == null) {
                    out.write(beat); // also how a vanished client is noticed: the write fails
                }
                // write everything queued, then flush once
                while (frame != null) {
                    if (frame == EventSession.END) {
                        out.flush();
                        return;
                    }
                    out.write(frame.bytes());
                    frame = session.next(generation, 0);
                }
            } catch (InterruptedException e) {
                return; // the server is being torn down
            }
            out.flush();
        }
    }

    // ---- answers ----

    private static void send(HttpServletResponse response, int status, ByteArrayOutputStream body) throws IOException {
        response.setStatus(status);
        response.setContentType(Wire.MEDIA_TYPE);
        response.setContentLength(body.size());
        body.writeTo(response.getOutputStream());
    }

    private void error(HttpServletResponse response, WireError kind, String message, boolean written)
            throws IOException {
        if (response.isCommitted()) {
            return;
        }
        ByteArrayOutputStream body = new ByteArrayOutputStream(128);
        try (WireWriter out = state.wire.writer(body)) {
            out.startObject().field("error", kind.kind()).field("message", truncate(message, MAX_MESSAGE_CHARS));
            if (written) {
                out.field("written", true);
            }
            out.endObject();
        }
        if (kind == WireError.BUSY || kind == WireError.STOPPING) {
            response.setHeader("Retry-After", "1");
        }
        send(response, kind.status(), body);
    }

    private static String truncate(String text) {
        return truncate(text, 40);
    }

    private static String truncate(String text, int max) {
        if (text == null) {
            return "";
        }
        return text.length() <= max ? text : text.substring(0, max) + "...";
    }
}
