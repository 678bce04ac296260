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

        @Override
        public CompletionStage<?> onBinary(WebSocket socket, ByteBuffer data, boolean last) {
            socket.request(1);
            return null;
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
