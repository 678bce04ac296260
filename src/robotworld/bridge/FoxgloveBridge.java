package robotworld.bridge;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.InetAddress;
import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArraySet;
import java.util.concurrent.atomic.AtomicLong;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.HttpConfiguration;
import org.eclipse.jetty.server.HttpConnectionFactory;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.thread.QueuedThreadPool;
import org.eclipse.jetty.websocket.api.Session;
import org.eclipse.jetty.websocket.server.WebSocketUpgradeHandler;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.observe.ActuatorStopped;
import robotworld.observe.AnswerSeen;
import robotworld.observe.Gap;
import robotworld.observe.GroundTruth;
import robotworld.observe.Liveness;
import robotworld.observe.ReplayMark;
import robotworld.observe.RequestSeen;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldObserver;
import robotworld.telemetry.TelemetryMessage;
import robotworld.telemetry.Topic;
import robotworld.telemetry.Topics;
import robotworld.telemetry.TrafficJson;
import robotworld.telemetry.WorldTelemetry;

/**
 * Serves one world's traffic to Foxglove WebSocket clients (the contract is in the package documentation).
 *
 * <pre>{@code
 * try (FoxgloveBridge bridge = FoxgloveBridge.start(layout, FoxgloveBridge.Options.defaults().port(0));
 *      WorldTap tap = new WorldTap(space, layout)) {
 *     tap.add(bridge.observer()).start();
 *     System.out.println("connect Foxglove to " + bridge.uri());
 *     ...
 * }
 * }</pre>
 */
public final class FoxgloveBridge implements AutoCloseable {

    /** The WebSocket subprotocol spoken. */
    public static final String SUBPROTOCOL = "foxglove.websocket.v1";
    private static final Logger LOG = LoggerFactory.getLogger(FoxgloveBridge.class);
    private static final byte MESSAGE_DATA = 0x01;

    /**
     * How the endpoint runs.
     *
     * @param bindAddress     address to listen on; loopback by default
     * @param port            TCP port (0: any free one); 8765 by default, as Foxglove suggests
     * @param token           the token clients must send, or null for none
     * @param maxClients      most connections at once
     * @param clientBacklog   messages that may wait to be sent to one client before its messages are dropped
     * @param maxClientFrame  largest text or binary frame accepted from a client, bytes
     */
    public record Options(String bindAddress, int port, String token, int maxClients, int clientBacklog,
                          int maxClientFrame) {

        /** The port used when none is given. */
        public static final int DEFAULT_PORT = 8765;

        /** Checks the values. */
        public Options {
            Objects.requireNonNull(bindAddress, "bindAddress");
            if (port < 0 || port > 65_535 || maxClients < 1 || clientBacklog < 1 || maxClientFrame < 1024) {
                throw new IllegalArgumentException("port 0..65535 and positive limits (frames at least 1 KiB)");
            }
            if (token != null && (token.isBlank() || !token.strip().equals(token))) {
                throw new IllegalArgumentException("a token must be non-blank, without surrounding spaces");
            }
        }

        /** Loopback, port 8765, no token, 16 clients, 4096 messages of backlog each, 64 KiB client frames. */
        public static Options defaults() {
            return new Options("127.0.0.1", DEFAULT_PORT, null, 16, 4096, 64 * 1024);
        }

        /** With another port. */
        public Options port(int newPort) {
            return new Options(bindAddress, newPort, token, maxClients, clientBacklog, maxClientFrame);
        }

        /** With another address to listen on. */
        public Options bindAddress(String address) {
            return new Options(address, port, token, maxClients, clientBacklog, maxClientFrame);
        }

        /** With a token clients must send. */
        public Options token(String newToken) {
            return new Options(bindAddress, port, newToken, maxClients, clientBacklog, maxClientFrame);
        }

        /** With another client limit. */
        public Options maxClients(int clients) {
            return new Options(bindAddress, port, token, clients, clientBacklog, maxClientFrame);
        }

        /** With another per-client backlog. */
        public Options clientBacklog(int messages) {
            return new Options(bindAddress, port, token, maxClients, messages, maxClientFrame);
        }
    }

    private final WorldLayout layout;
    private final Options options;
    private final Server jetty;
    private final URI uri;
    private final String sessionId = Long.toString(System.currentTimeMillis());
    private final Set<Client> clients = new CopyOnWriteArraySet<>();
    private final AtomicLong published = new AtomicLong();
    private final WorldObserver observer;
    private final byte[] token;

    // ---- guarded by this (a client's lock may be held when taking it, never the other way round) ----
    private final Map<String, Integer> channelIds = new LinkedHashMap<>();
    private final Map<Integer, Topic> channels = new LinkedHashMap<>();
    private final Map<Integer, Published> latest = new HashMap<>();
    private long sequence;
    private ReplayMark replay;

    /** A message as published: numbered, so that a client that subscribes meanwhile gets it exactly once. */
    private record Published(long sequence, TelemetryMessage message) {
    }

    private FoxgloveBridge(WorldLayout layout, Options options) {
        this.layout = layout;
        this.options = options;
        this.token = options.token() == null ? null : options.token().getBytes(StandardCharsets.UTF_8);
        for (Topic topic : Topics.known(layout)) {
            channel(topic);
        }
        WorldTelemetry telemetry = new WorldTelemetry(this::publish);
        this.observer = new Forwarder(telemetry);
        QueuedThreadPool threads = new QueuedThreadPool(Math.max(16, options.maxClients() + 8), 2);
        threads.setName("foxglove-bridge");
        threads.setDaemon(true);
        jetty = new Server(threads);
        HttpConfiguration http = new HttpConfiguration();
        http.setSendServerVersion(false);
        http.setRequestHeaderSize(8 * 1024);
        ServerConnector connector = new ServerConnector(jetty, 1, 1, new HttpConnectionFactory(http));
        connector.setHost(options.bindAddress());
        connector.setPort(options.port());
        connector.setIdleTimeout(60_000);
        jetty.addConnector(connector);
        WebSocketUpgradeHandler upgrade = WebSocketUpgradeHandler.from(jetty, container -> {
            container.setMaxTextMessageSize(options.maxClientFrame());
            container.setMaxBinaryMessageSize(options.maxClientFrame());
            container.setIdleTimeout(Duration.ofMinutes(10));
            container.addMapping("/*", (request, response, callback) -> {
                String refusal = refusal(request);
                if (refusal != null) {
                    int status = refusal.startsWith("401") ? 401 : refusal.startsWith("503") ? 503 : 400;
                    Response.writeError(request, response, callback, status, refusal.substring(4));
                    return null;
                }
                response.setAcceptedSubProtocol(SUBPROTOCOL);
                return new Client();
            });
        });
        upgrade.setHandler(new NotAWebSocket());
        jetty.setHandler(upgrade);
        try {
            connector.open();
        } catch (IOException e) {
            // the reason ("Address already in use") is the innermost cause; each command names its own option
            Throwable reason = e;
            while (reason.getCause() != null && reason.getCause().getMessage() != null) {
                reason = reason.getCause();
            }
            throw new IllegalStateException("cannot listen on " + options.bindAddress() + ":" + options.port()
                    + " for Foxglove: " + reason.getMessage(), e);
        }
        String host = options.bindAddress();
        if (host.equals("0.0.0.0") || host.equals("::")) {
            try {
                host = InetAddress.getLocalHost().getHostName();
            } catch (IOException e) {
                host = "localhost";
            }
        }
        uri = URI.create("ws://" + (host.contains(":") ? "[" + host + "]" : host) + ":" + connector.getLocalPort()
                + "/");
    }

    /**
     * Starts the endpoint for {@code layout}'s world.
     *
     * @throws IllegalStateException when it cannot listen (port taken) or start
     */
    public static FoxgloveBridge start(WorldLayout layout, Options options) {
        FoxgloveBridge bridge = new FoxgloveBridge(Objects.requireNonNull(layout, "layout"),
                Objects.requireNonNull(options, "options"));
        try {
            bridge.jetty.start();
        } catch (Exception e) {
            bridge.close();
            throw new IllegalStateException("cannot start the Foxglove endpoint: " + e.getMessage(), e);
        }
        return bridge;
    }

    /** Where clients connect, e.g. {@code ws://127.0.0.1:8765/}. */
    public URI uri() {
        return uri;
    }

    /** The observer to add to the world's tap. */
    public WorldObserver observer() {
        return observer;
    }

    /** Clients connected now. */
    public int clientCount() {
        return clients.size();
    }

    /** Subscriptions of all clients together. */
    public int subscriptionCount() {
        int count = 0;
        for (Client client : clients) {
            synchronized (client) {
                count += client.subscriptions.size();
            }
        }
        return count;
    }

    /** Messages published so far (to however many subscribers). */
    public long published() {
        return published.get();
    }

    /** Messages dropped for slow clients so far, all clients together. */
    public long dropped() {
        return clients.stream().mapToLong(client -> client.dropped.get()).sum();
    }

    @Override
    public void close() {
        for (Client client : clients) {
            client.close();
        }
        try {
            jetty.stop();
        } catch (Exception e) {
            LOG.warn("stopping the Foxglove endpoint: {}", e.getMessage());
        }
    }

    // ---- what the tap delivers ----

    /** Publishes one message to the subscribers of its topic (advertising the topic first if it is new). */
    public void publish(TelemetryMessage message) {
        List<Client> targets;
        int channel;
        boolean isNew;
        Published numbered;
        synchronized (this) {
            isNew = !channelIds.containsKey(message.topic().name());
            channel = channel(message.topic());
            numbered = new Published(++sequence, message);
            latest.put(channel, numbered);
        }
        if (isNew) {
            String advertise = advertise(List.of(channel));
            clients.forEach(client -> client.sendText(advertise));
        }
        published.incrementAndGet();
        targets = List.copyOf(clients);
        for (Client client : targets) {
            client.deliver(channel, numbered);
        }
    }

    private synchronized int channel(Topic topic) {
        Integer id = channelIds.get(topic.name());
        if (id == null) {
            id = channelIds.size() + 1;
            channelIds.put(topic.name(), id);
            channels.put(id, topic);
        }
        return id;
    }

    private void replay(ReplayMark mark) {
        synchronized (this) {
            replay = mark;
        }
        String status = status(0, mark.label() + ": this is a recorded run, not a live world");
        clients.forEach(client -> client.sendText(status));
    }

    /** Forwards the tap's events to the telemetry, and notes a replay. */
    private final class Forwarder implements WorldObserver {
        private final WorldTelemetry telemetry;

        Forwarder(WorldTelemetry telemetry) {
            this.telemetry = telemetry;
        }

        @Override
        public void requestSeen(RequestSeen event) {
            telemetry.requestSeen(event);
        }

        @Override
        public void answerSeen(AnswerSeen event) {
            telemetry.answerSeen(event);
        }

        @Override
        public void liveness(Liveness event) {
            telemetry.liveness(event);
        }

        @Override
        public void actuatorStopped(ActuatorStopped event) {
            telemetry.actuatorStopped(event);
        }

        @Override
        public void groundTruth(GroundTruth frame) {
            telemetry.groundTruth(frame);
        }

        @Override
        public void replay(ReplayMark mark) {
            FoxgloveBridge.this.replay(mark);
        }

        @Override
        public void gap(Gap gap) {
            telemetry.gap(gap);
        }
    }

    // ---- the protocol ----

    /** Why an upgrade request is refused ("401 ...", "400 ...", "503 ..."), or null to accept it. */
    private String refusal(org.eclipse.jetty.websocket.server.ServerUpgradeRequest request) {
        if (token != null && !hasToken(request)) {
            return "401 this endpoint needs its token: 'Authorization: Bearer <token>' or ?token=<token> in the URL";
        }
        if (!request.hasSubProtocol(SUBPROTOCOL)) {
            return "400 this endpoint speaks the WebSocket subprotocol " + SUBPROTOCOL + " only";
        }
        if (clients.size() >= options.maxClients()) {
            return "503 too many clients (at most " + options.maxClients() + ")";
        }
        return null;
    }

    private boolean hasToken(Request request) {
        String header = request.getHeaders().get("Authorization");
        if (header != null && header.startsWith("Bearer ") && same(header.substring(7))) {
            return true;
        }
        String query = Request.extractQueryParameters(request).getValue("token");
        return query != null && same(query);
    }

    private boolean same(String offered) {
        return MessageDigest.isEqual(token, offered.getBytes(StandardCharsets.UTF_8));
    }

    private String serverInfo() {
        ObjectNode info = TrafficJson.MAPPER.createObjectNode();
        info.put("op", "serverInfo");
        ReplayMark mark;
        synchronized (this) {
            mark = replay;
        }
        info.put("name", "RobotWorldExplorer: " + layout.world() + (mark == null ? "" : " - " + mark.label()));
        info.putArray("capabilities");
        ObjectNode metadata = info.putObject("metadata");
        metadata.put("world", layout.world());
        metadata.put("replay", mark == null ? "false" : mark.label());
        info.put("sessionId", sessionId);
        return info.toString();
    }

    private String advertise(List<Integer> ids) {
        ObjectNode message = TrafficJson.MAPPER.createObjectNode();
        message.put("op", "advertise");
        ArrayNode list = message.putArray("channels");
        synchronized (this) {
            for (int id : ids) {
                Topic topic = channels.get(id);
                list.addObject().put("id", id).put("topic", topic.name()).put("encoding", Topic.MESSAGE_ENCODING)
                        .put("schemaName", topic.schemaName()).put("schema", topic.schema())
                        .put("schemaEncoding", Topic.SCHEMA_ENCODING);
            }
        }
        return message.toString();
    }

    private static String status(int level, String text) {
        ObjectNode status = TrafficJson.MAPPER.createObjectNode();
        status.put("op", "status");
        status.put("level", level);
        status.put("message", text);
        return status.toString();
    }

    private static ByteBuffer messageData(int subscription, long timeNanos, byte[] payload) {
        ByteBuffer frame = ByteBuffer.allocate(1 + 4 + 8 + payload.length).order(ByteOrder.LITTLE_ENDIAN);
        frame.put(MESSAGE_DATA).putInt(subscription).putLong(timeNanos).put(payload);
        return frame.flip();
    }

    /** One connected client: its subscriptions and its bounded backlog. */
    /** Public only because Jetty calls its listener methods reflectively; not part of the API. */
    public final class Client implements Session.Listener.AutoDemanding {

        private Client() {
        }

        private volatile Session session;
        /** channel id -> subscription id; guarded by this client. */
        private final Map<Integer, Integer> subscriptions = new HashMap<>();
        /** channel id -> the sequence number of the last message sent on it; guarded by this client. */
        private final Map<Integer, Long> sentUpTo = new HashMap<>();
        private final AtomicLong inFlight = new AtomicLong();
        private final AtomicLong dropped = new AtomicLong();
        private long droppedReported;

        @Override
        public void onWebSocketOpen(Session opened) {
            session = opened;
            clients.add(this);
            sendText(serverInfo());
            List<Integer> ids;
            ReplayMark mark;
            synchronized (FoxgloveBridge.this) {
                ids = new ArrayList<>(channels.keySet());
                mark = replay;
            }
            sendText(advertise(ids));
            if (mark != null) {
                sendText(status(0, mark.label() + ": this is a recorded run, not a live world"));
            }
        }

        @Override
        public void onWebSocketText(String text) {
            JsonNode message;
            try {
                message = TrafficJson.MAPPER.readTree(text);
            } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
                sendText(status(2, "not JSON: " + shorten(e.getOriginalMessage())));
                return;
            }
            String op = message.path("op").asText("");
            switch (op) {
                case "subscribe" -> subscribe(message.path("subscriptions"));
                case "unsubscribe" -> unsubscribe(message.path("subscriptionIds"));
                default -> sendText(status(1, "this endpoint does not support op \"" + shorten(op)
                        + "\" (it only shows the world: subscribe and unsubscribe)"));
            }
        }

        @Override
        public void onWebSocketBinary(ByteBuffer payload, org.eclipse.jetty.websocket.api.Callback callback) {
            callback.succeed();
            sendText(status(1, "this endpoint takes no client messages (no clientPublish, no services)"));
        }

        private void subscribe(JsonNode list) {
            if (!list.isArray()) {
                sendText(status(2, "subscribe needs \"subscriptions\": [{\"id\", \"channelId\"}]"));
                return;
            }
            for (JsonNode entry : list) {
                int id = entry.path("id").asInt(-1);
                int channel = entry.path("channelId").asInt(-1);
                // under this client's lock from reading the latest message to sending it: a message published
                // meanwhile is delivered after it (deliver waits for the lock), and only if it is newer
                synchronized (this) {
                    Published last;
                    boolean known;
                    synchronized (FoxgloveBridge.this) {
                        known = channels.containsKey(channel);
                        last = latest.get(channel);
                    }
                    if (!known) { // sent outside the bridge's lock, which every publication takes
                        sendText(status(2, "no channel " + channel));
                        continue;
                    }
                    if (id < 0 || subscriptions.containsValue(id)) {
                        sendText(status(2, "subscription id " + id + " is invalid or in use"));
                        continue;
                    }
                    Integer existing = subscriptions.get(channel);
                    if (existing != null) {
                        // the protocol allows one subscription per channel and client: keep the first
                        sendText(status(2, "channel " + channel + " is already subscribed as subscription " + existing
                                + "; subscription " + id + " ignored (unsubscribe " + existing + " first)"));
                        continue;
                    }
                    subscriptions.put(channel, id);
                    sentUpTo.put(channel, last == null ? 0L : last.sequence());
                    if (last != null) {
                        send(id, last.message());
                    }
                }
            }
        }

        private void unsubscribe(JsonNode ids) {
            if (!ids.isArray()) {
                sendText(status(2, "unsubscribe needs \"subscriptionIds\": [id, ...]"));
                return;
            }
            synchronized (this) {
                for (JsonNode id : ids) {
                    int wanted = id.asInt(-1);
                    if (!subscriptions.values().removeIf(value -> value == wanted)) {
                        sendText(status(1, "no subscription " + shorten(id.asText()) + " to end"));
                    }
                }
            }
        }

        /**
         * Sends a message to this client if it subscribed to the channel, unless it was sent already (as the latest
         * message when the subscription began).
         */
        void deliver(int channel, Published published) {
            synchronized (this) {
                Integer subscription = subscriptions.get(channel);
                if (subscription != null && published.sequence() > sentUpTo.getOrDefault(channel, 0L)) {
                    sentUpTo.put(channel, published.sequence());
                    send(subscription, published.message());
                }
            }
        }

        /** Under this client's lock, so a channel's messages go out in order. */
        private void send(int subscription, TelemetryMessage message) {
            Session open = session;
            if (open == null || !open.isOpen()) {
                return;
            }
            if (inFlight.get() >= options.clientBacklog()) {
                dropped.incrementAndGet();
                return;
            }
            long lost = dropped.get();
            if (lost > droppedReported) {
                droppedReported = lost;
                sendText(status(1, lost + " messages dropped in all: this connection is too slow for the world's"
                        + " traffic"));
            }
            inFlight.incrementAndGet();
            open.sendBinary(messageData(subscription, message.timeNanos(), message.json()), done());
        }

        void sendText(String text) {
            Session open = session;
            if (open != null && open.isOpen()) {
                inFlight.incrementAndGet();
                open.sendText(text, done());
            }
        }

        private org.eclipse.jetty.websocket.api.Callback done() {
            return org.eclipse.jetty.websocket.api.Callback.from(inFlight::decrementAndGet,
                    failure -> inFlight.decrementAndGet());
        }

        @Override
        public void onWebSocketClose(int status, String reason, org.eclipse.jetty.websocket.api.Callback callback) {
            clients.remove(this);
            callback.succeed();
        }

        @Override
        public void onWebSocketError(Throwable cause) {
            clients.remove(this);
            LOG.debug("Foxglove client failed: {}", cause.toString());
        }

        void close() {
            Session open = session;
            if (open != null) {
                open.close(1001, "the endpoint is stopping", org.eclipse.jetty.websocket.api.Callback.NOOP);
            }
        }
    }

    private static String shorten(String text) {
        if (text == null) {
            return "";
        }
        return text.length() > 40 ? text.substring(0, 40) + "..." : text;
    }

    /** Answers plain HTTP requests: this port speaks WebSocket only. */
    private static final class NotAWebSocket extends Handler.Abstract {
        @Override
        public boolean handle(Request request, Response response, Callback callback) {
            Response.writeError(request, response, callback, 426, "this is a Foxglove WebSocket endpoint ("
                    + SUBPROTOCOL + "): connect Foxglove or Lichtblick to ws://<host>:<port>/");
            return true;
        }
    }
}
