package robotworld.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.net.http.WebSocketHandshakeException;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robotworld.observe.ModuleRef;
import robotworld.observe.ReplayMark;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldTap;
import robotworld.space.EmbeddedSpace;
import robotworld.telemetry.TelemetryMessage;
import robotworld.telemetry.Topic;
import robotworld.telemetry.Topics;

/** Who may connect, what a wrong request gets, and how a replay is told, with the JDK's WebSocket client. */
class FoxgloveBridgeRulesTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final WorldLayout LAYOUT = new WorldLayout("RulesWorld", List.of(new WorldLayout.Participant(
            "Bot", "robot", List.of(new ModuleRef("Bot", "Motor", "MotorModule")))));
    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();

    /** Text frames a client received, in order. */
    private static final class Texts implements WebSocket.Listener {
        final LinkedBlockingQueue<String> texts = new LinkedBlockingQueue<>();
        private final StringBuilder partial = new StringBuilder();

        @Override
        public CompletionStage<?> onText(WebSocket socket, CharSequence data, boolean last) {
            partial.append(data);
            if (last) {
                texts.add(partial.toString());
                partial.setLength(0);
            }
            socket.request(1);
            return null;
        }

        /** Message Data frames as "subscription id: JSON". */
        final LinkedBlockingQueue<String> messages = new LinkedBlockingQueue<>();
        private final java.io.ByteArrayOutputStream binary = new java.io.ByteArrayOutputStream();

        @Override
        public CompletionStage<?> onBinary(WebSocket socket, ByteBuffer data, boolean last) {
            byte[] piece = new byte[data.remaining()];
            data.get(piece);
            binary.writeBytes(piece);
            if (last) {
                ByteBuffer frame = ByteBuffer.wrap(binary.toByteArray()).order(java.nio.ByteOrder.LITTLE_ENDIAN);
                binary.reset();
                if (frame.get() == 1) { // Message Data: opcode, subscription id, timestamp, payload
                    int subscription = frame.getInt();
                    frame.getLong();
                    messages.add(subscription + ": " + java.nio.charset.StandardCharsets.UTF_8.decode(frame));
                }
            }
            socket.request(1);
            return null;
        }

        String nextMessage() throws Exception {
            String message = messages.poll(30, TimeUnit.SECONDS);
            if (message == null) {
                throw new AssertionError("no Message Data within 30 s");
            }
            return message;
        }

        JsonNode next() throws Exception {
            String text = texts.poll(30, TimeUnit.SECONDS);
            if (text == null) {
                throw new AssertionError("no message within 30 s");
            }
            return JSON.readTree(text);
        }
    }

    private CompletableFuture<WebSocket> connect(URI uri, Texts listener, String... subprotocols) {
        WebSocket.Builder builder = http.newWebSocketBuilder().connectTimeout(Duration.ofSeconds(10));
        if (subprotocols.length > 0) {
            builder.subprotocols(subprotocols[0], java.util.Arrays.copyOfRange(subprotocols, 1, subprotocols.length));
        }
        return builder.buildAsync(uri, listener);
    }

    private static int refusedWith(CompletableFuture<WebSocket> attempt) throws InterruptedException {
        try {
            attempt.get(30, TimeUnit.SECONDS);
            throw new AssertionError("the connection was accepted");
        } catch (ExecutionException e) {
            assertTrue(e.getCause() instanceof WebSocketHandshakeException, e.getCause().toString());
            return ((WebSocketHandshakeException) e.getCause()).getResponse().statusCode();
        } catch (java.util.concurrent.TimeoutException e) {
            throw new AssertionError("no answer within 30 s");
        }
    }

    @Test
    void withATokenOnlyClientsThatSendItConnect() throws Exception {
        try (FoxgloveBridge bridge = FoxgloveBridge.start(LAYOUT, FoxgloveBridge.Options.defaults().port(0)
                .token("s3cret"))) {
            assertEquals("127.0.0.1", bridge.uri().getHost(), "loopback by default");
            assertEquals(401, refusedWith(connect(bridge.uri(), new Texts(), FoxgloveBridge.SUBPROTOCOL)));
            assertEquals(401, refusedWith(connect(URI.create(bridge.uri() + "?token=wrong"), new Texts(),
                    FoxgloveBridge.SUBPROTOCOL)));
            Texts texts = new Texts();
            WebSocket socket = connect(URI.create(bridge.uri() + "?token=s3cret"), texts, FoxgloveBridge.SUBPROTOCOL)
                    .get(30, TimeUnit.SECONDS);
            assertEquals(FoxgloveBridge.SUBPROTOCOL, socket.getSubprotocol());
            assertEquals("serverInfo", texts.next().get("op").asText());
            JsonNode advertise = texts.next();
            assertEquals("advertise", advertise.get("op").asText());
            assertEquals("/Bot/Motor", advertise.at("/channels/0/topic").asText());
            socket.abort();
        }
    }

    @Test
    void wrongRequestsGetClearAnswersAndTheEndpointKeepsServing() throws Exception {
        try (FoxgloveBridge bridge = FoxgloveBridge.start(LAYOUT, FoxgloveBridge.Options.defaults().port(0)
                .maxClients(1))) {
            URI plain = URI.create(bridge.uri().toString().replace("ws://", "http://"));
            HttpResponse<String> page = http.send(HttpRequest.newBuilder(plain).timeout(Duration.ofSeconds(30))
                    .build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(426, page.statusCode());
            assertEquals(400, refusedWith(connect(bridge.uri(), new Texts(), "some.other.protocol")));
            assertEquals(400, refusedWith(connect(bridge.uri(), new Texts())));

            Texts texts = new Texts();
            WebSocket socket = connect(bridge.uri(), texts, FoxgloveBridge.SUBPROTOCOL).get(30, TimeUnit.SECONDS);
            texts.next();
            texts.next();
            assertEquals(503, refusedWith(connect(bridge.uri(), new Texts(), FoxgloveBridge.SUBPROTOCOL)),
                    "one client at most");
            socket.sendText("{not json", true).get(30, TimeUnit.SECONDS);
            JsonNode status = texts.next();
            assertEquals("status", status.get("op").asText());
            assertEquals(2, status.get("level").asInt());
            socket.sendText("{\"op\":\"setParameters\",\"parameters\":[]}", true).get(30, TimeUnit.SECONDS);
            assertTrue(texts.next().get("message").asText().contains("does not support"));
            socket.sendText("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":999}]}", true)
                    .get(30, TimeUnit.SECONDS);
            assertTrue(texts.next().get("message").asText().contains("no channel 999"));
            socket.sendText("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":1}]}", true)
                    .get(30, TimeUnit.SECONDS);
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (bridge.subscriptionCount() < 1 && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertEquals(1, bridge.subscriptionCount(), "still serving after the bad messages");
            socket.abort();
        }
    }

    @Test
    void aChannelHasOneSubscriptionPerClientAndUnsubscribeEndsIt() throws Exception {
        Topic motor = Topics.module(new ModuleRef("Bot", "Motor", "MotorModule"));
        try (FoxgloveBridge bridge = FoxgloveBridge.start(LAYOUT, FoxgloveBridge.Options.defaults().port(0))) {
            Texts texts = new Texts();
            WebSocket socket = connect(bridge.uri(), texts, FoxgloveBridge.SUBPROTOCOL).get(30, TimeUnit.SECONDS);
            texts.next(); // serverInfo
            int channel = channelOf(texts.next(), "/Bot/Motor");
            send(socket, "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":7,\"channelId\":" + channel + "}]}");
            awaitSubscriptions(bridge, 1);
            bridge.publish(new TelemetryMessage(motor, 1, "{\"n\":1}".getBytes()));
            assertEquals("7: {\"n\":1}", texts.nextMessage());

            // a second subscription to the same channel is refused, and the first one stays
            send(socket, "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":8,\"channelId\":" + channel + "}]}");
            JsonNode refused = texts.next();
            assertEquals(2, refused.get("level").asInt(), refused.toString());
            assertTrue(refused.get("message").asText().contains("already subscribed as subscription 7"),
                    refused.toString());
            assertEquals(1, bridge.subscriptionCount());
            bridge.publish(new TelemetryMessage(motor, 2, "{\"n\":2}".getBytes()));
            assertEquals("7: {\"n\":2}", texts.nextMessage(), "once, under the first subscription's id");

            // after unsubscribing, nothing more comes for that id
            send(socket, "{\"op\":\"unsubscribe\",\"subscriptionIds\":[7]}");
            awaitSubscriptions(bridge, 0);
            bridge.publish(new TelemetryMessage(motor, 3, "{\"n\":3}".getBytes()));
            // frames go out in order: when the answer to a later request has come, so would have the message
            send(socket, "{\"op\":\"unsubscribe\",\"subscriptionIds\":[7]}");
            JsonNode unknown = texts.next();
            assertEquals(1, unknown.get("level").asInt(), unknown.toString());
            assertTrue(unknown.get("message").asText().contains("no subscription 7"), unknown.toString());
            assertTrue(texts.messages.isEmpty(), "no message after unsubscribing: " + texts.messages);

            // the id may be used again: the new subscription starts with the channel's latest message
            send(socket, "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":7,\"channelId\":" + channel + "}]}");
            assertEquals("7: {\"n\":3}", texts.nextMessage());
            socket.abort();
        }
    }

    @Test
    void aClientSubscribingWhileMessagesComeGetsEachOnceFromTheLatestOn() throws Exception {
        // a subscription starts with the channel's latest message and then gets every later one: none lost, none
        // twice, however a Subscribe and a publish of the world's tap interleave
        Topic motor = Topics.module(new ModuleRef("Bot", "Motor", "MotorModule"));
        try (FoxgloveBridge bridge = FoxgloveBridge.start(LAYOUT, FoxgloveBridge.Options.defaults().port(0)
                .clientBacklog(1_000_000))) {
            Texts texts = new Texts();
            WebSocket socket = connect(bridge.uri(), texts, FoxgloveBridge.SUBPROTOCOL).get(30, TimeUnit.SECONDS);
            texts.next(); // serverInfo
            int channel = channelOf(texts.next(), "/Bot/Motor");
            java.util.concurrent.atomic.AtomicBoolean publishing = new java.util.concurrent.atomic.AtomicBoolean(true);
            Thread tap = new Thread(() -> {
                for (long n = 1; publishing.get(); n++) {
                    bridge.publish(new TelemetryMessage(motor, n, ("{\"n\":" + n + "}").getBytes()));
                    if (n % 8 == 0) {
                        java.util.concurrent.locks.LockSupport.parkNanos(1_000); // the client keeps up
                    }
                }
            }, "publishing");
            tap.start();
            try {
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(3); // it took < 2 s to go wrong
                for (int id = 1; System.nanoTime() < deadline; id++) {
                    send(socket, "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":" + id + ",\"channelId\":"
                            + channel + "}]}");
                    List<Long> got = new java.util.ArrayList<>();
                    while (got.size() < 3) {
                        String message = texts.nextMessage();
                        if (message.startsWith(id + ": ")) {
                            got.add(JSON.readTree(message.substring(message.indexOf(' ') + 1)).get("n").asLong());
                        }
                    }
                    assertEquals(List.of(got.get(0), got.get(0) + 1, got.get(0) + 2), got,
                            "subscription " + id + ": from the latest on, each message once");
                    send(socket, "{\"op\":\"unsubscribe\",\"subscriptionIds\":[" + id + "]}");
                }
            } finally {
                publishing.set(false);
                tap.join(10_000);
            }
            assertEquals(0, bridge.dropped(), "nothing dropped for a slow client: a gap would not be the race");
            socket.abort();
        }
    }

    private static int channelOf(JsonNode advertise, String topic) {
        assertEquals("advertise", advertise.get("op").asText());
        for (JsonNode channel : advertise.get("channels")) {
            if (channel.get("topic").asText().equals(topic)) {
                return channel.get("id").asInt();
            }
        }
        throw new AssertionError(topic + " not advertised: " + advertise);
    }

    private static void send(WebSocket socket, String text) throws Exception {
        socket.sendText(text, true).get(30, TimeUnit.SECONDS);
    }

    private static void awaitSubscriptions(FoxgloveBridge bridge, int count) throws InterruptedException {
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (bridge.subscriptionCount() != count && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        assertEquals(count, bridge.subscriptionCount());
    }

    @Test
    void aReplayIsToldInTheServerNameAndAStatusMessage() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open();
             FoxgloveBridge bridge = FoxgloveBridge.start(LAYOUT, FoxgloveBridge.Options.defaults().port(0))) {
            new ReplayMark("run.mcap", Instant.parse("2026-11-23T10:00:00Z"), 2).publish(space);
            WorldTap tap = new WorldTap(space, LAYOUT).add(bridge.observer()).start();
            try {
                long deadline = System.nanoTime() + 30_000_000_000L;
                Texts texts;
                JsonNode info;
                WebSocket socket;
                while (true) {
                    // the tap hands the mark over on its own thread: connect until the server says so
                    texts = new Texts();
                    socket = connect(bridge.uri(), texts, FoxgloveBridge.SUBPROTOCOL).get(30, TimeUnit.SECONDS);
                    info = texts.next();
                    if (info.get("name").asText().contains("REPLAY") || System.nanoTime() > deadline) {
                        break;
                    }
                    socket.abort();
                    Thread.sleep(20);
                }
                assertTrue(info.get("name").asText().contains("REPLAY of run.mcap"), info.toString());
                assertTrue(info.at("/metadata/replay").asText().contains("2x"), info.toString());
                texts.next(); // advertise
                JsonNode status = texts.next();
                assertEquals("status", status.get("op").asText());
                assertTrue(status.get("message").asText().contains("recorded run"), status.toString());
                socket.abort();
            } finally {
                tap.close();
            }
        }
    }
}
