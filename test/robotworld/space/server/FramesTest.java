package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.wire.Frames;

/**
 * The framed form of operation requests, spoken byte by byte as the wire format describes it (not through our
 * client): an HTTP/1.1 upgrade on the space's path, then the same operations and answers as over HTTP, a frame that cannot be read refused with 400 and the
 * connection closed, an oversized frame refused with 413 before its body is sent, the token checked on every
 * frame, HTTP still served on the same port; and a {@code RemoteSpace} using frames once the server offers them.
 */
@org.junit.jupiter.api.Timeout(60)
class FramesTest {

    /** A raw framed connection. */
    private static final class Framed implements AutoCloseable {
        final Socket socket = new Socket();
        final OutputStream out;
        final DataInputStream in;
        /** The head of the server's answer to the upgrade request. */
        final String upgradeAnswer;

        Framed(URI server) throws IOException {
            this(server, server.getPath());
        }

        /** Connects and asks for frames on {@code path}. */
        Framed(URI server, String path) throws IOException {
            socket.connect(new InetSocketAddress(server.getHost(), server.getPort()), 2_000);
            socket.setSoTimeout(5_000);
            out = socket.getOutputStream();
            in = new DataInputStream(socket.getInputStream());
            out.write(("GET " + path + " HTTP/1.1\r\nHost: test\r\nConnection: Upgrade\r\nUpgrade: "
                    + Frames.PROTOCOL + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
            out.flush();
            StringBuilder head = new StringBuilder();
            while (!head.toString().endsWith("\r\n\r\n")) {
                int b = in.read();
                if (b < 0) {
                    break;
                }
                head.append((char) b);
            }
            upgradeAnswer = head.toString();
        }

        boolean upgraded() {
            return upgradeAnswer.startsWith("HTTP/1.1 101 ");
        }

        void sendRaw(byte[] bytes) throws IOException {
            out.write(bytes);
            out.flush();
        }

        void send(String operation, String token, String acks, String json) throws IOException {
            byte[] name = operation.getBytes(StandardCharsets.US_ASCII);
            byte[] tokenBytes = token == null ? new byte[0] : token.getBytes(StandardCharsets.UTF_8);
            byte[] ackBytes = acks == null ? new byte[0] : acks.getBytes(StandardCharsets.US_ASCII);
            byte[] body = json.getBytes(StandardCharsets.UTF_8);
            int length = 1 + name.length + 2 + tokenBytes.length + 2 + ackBytes.length + body.length;
            sendRaw(ByteBuffer.allocate(4 + length).putInt(length).put((byte) name.length).put(name)
                    .putShort((short) tokenBytes.length).put(tokenBytes).putShort((short) ackBytes.length)
                    .put(ackBytes).put(body).array());
        }

        Answer receive() throws IOException {
            int length = in.readInt();
            int status = in.readUnsignedShort();
            int flags = in.readUnsignedByte();
            byte[] body = new byte[length - 3];
            in.readFully(body);
            return new Answer(status, flags, new String(body, StandardCharsets.UTF_8));
        }

        Answer exchange(String operation, String json) throws IOException {
            send(operation, null, null, json);
            return receive();
        }

        /** Whether the server closed the connection (reads end of stream). */
        boolean closedByServer() throws IOException {
            try {
                return in.read() < 0;
            } catch (EOFException | java.net.SocketException e) {
                return true;
            }
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    private record Answer(int status, int flags, String body) {
    }

    private static SpaceServer start(String token) {
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100);
        return SpaceServer.start(token == null ? options : options.token(token));
    }

    @Test
    void operationsSpokenAsFramesGetTheSameAnswersAsOverHttp() throws Exception {
        try (SpaceServer server = start(null); Framed framed = new Framed(server.uri())) {
            assertTrue(framed.upgraded(), framed.upgradeAnswer);
            assertTrue(framed.upgradeAnswer.toLowerCase(java.util.Locale.ROOT).contains("upgrade: " + Frames.PROTOCOL),
                    framed.upgradeAnswer);
            Answer created = framed.exchange("lookupOrCreate", "{\"spec\":{\"name\":\"q\",\"order\":\"fifo\"}}");
            assertEquals(200, created.status(), created.body());
            String cref = created.body().substring(created.body().indexOf('{', 1), created.body().lastIndexOf('}'));
            assertEquals(200, framed.exchange("write", "{\"container\":" + cref
                    + ",\"timeout\":0,\"items\":[{\"entry\":\"hello\"},{\"entry\":7}],\"call\":\"w1\"}").status());
            Answer taken = framed.exchange("take", "{\"container\":" + cref
                    + ",\"timeout\":1000,\"selectors\":[{\"order\":\"fifo\",\"count\":\"all\"}],\"call\":\"t1\"}");
            assertEquals(200, taken.status(), taken.body());
            assertEquals("{\"ack\":true,\"entries\":[\"hello\",7]}", taken.body());
            // the confirmation rides on the next frame, as the Space-Ack header does over HTTP
            framed.send("ack", null, "t1", "{}");
            Answer acked = framed.receive();
            assertEquals(200, acked.status(), acked.body());
            Answer unknown = framed.exchange("teleport", "{}");
            assertEquals(404, unknown.status(), unknown.body());
            assertEquals(0, unknown.flags() & Frames.CLOSING, "an error the frame could be read for keeps the connection");
            Answer badBody = framed.exchange("take", "{\"container\":" + cref + ",\"nonsense\":1}");
            assertEquals(400, badBody.status(), badBody.body());
            assertTrue(badBody.body().contains("\"error\""), badBody.body());
            // the HTTP face is on the same port
            RawHttp.Answer http = RawHttp.post(server.uri(), "/lookup", "application/json", "{\"name\":\"q\"}");
            assertEquals(200, http.status(), http.body());
            // as the background flush of a client's confirmations sends them: in the header only
            RawHttp.Answer ack = RawHttp.post(server.uri(), "/ack", "application/json", "{}", "Space-Ack: t1");
            assertEquals(200, ack.status(), ack.body());
        }
    }

    @Test
    void anUpgradeToFramesOnAnotherPathThanTheSpacesIsServedAsHttp() throws Exception {
        try (SpaceServer server = start(null); Framed elsewhere = new Framed(server.uri(), "/elsewhere")) {
            assertTrue(elsewhere.upgradeAnswer.startsWith("HTTP/1.1 404 "), elsewhere.upgradeAnswer);
        }
    }

    @Test
    void aWaitingTakeIsAnsweredByTheWriteOfAnotherConnection() throws Exception {
        try (SpaceServer server = start(null); Framed taker = new Framed(server.uri());
             Framed writer = new Framed(server.uri())) {
            String cref = createFifo(taker);
            sendTake(taker, cref, "t1");
            Thread.sleep(100);
            write42(writer, cref, "w1");
            assertEquals(TAKEN_42, taker.receive().body());
            // and the connection reads on after an answer sent from another connection's thread
            assertEquals(200, taker.exchange("describe", "{\"container\":" + cref + "}").status());
        }
    }

    @Test
    void aRequestSentBeforeTheAnswerToAWaitingTakeIsServedOnceThatAnswerIsOut() throws Exception {
        int before = AnswerRound.writeAtOnceUpTo;
        AnswerRound.writeAtOnceUpTo = 0; // the take's answer waits for the end of the write's round, however small
        try (SpaceServer server = start(null); Framed taker = new Framed(server.uri());
             Framed writer = new Framed(server.uri())) {
            String cref = createFifo(taker);
            sendTake(taker, cref, "t1");
            // sent while the take waits: the server reads it and keeps it until the take's answer is written
            taker.send("describe", null, null, "{\"container\":" + cref + "}");
            Thread.sleep(100);
            // the write is handled on a selector thread; the take's answer goes out at the end of its round, and
            // reading on there must not leave the request already read waiting for bytes that will not come
            write42(writer, cref, "w1");
            assertEquals(TAKEN_42, taker.receive().body());
            Answer described = taker.receive();
            assertEquals(200, described.status(), described.body());
            // nothing sent early this time: the connection waits for its next request with the selector's next round
            sendTake(taker, cref, "t2");
            Thread.sleep(100);
            write42(writer, cref, "w2");
            assertEquals(TAKEN_42, taker.receive().body());
            assertEquals(200, taker.exchange("describe", "{\"container\":" + cref + "}").status());
        } finally {
            AnswerRound.writeAtOnceUpTo = before;
        }
    }

    private static final String TAKEN_42 = "{\"ack\":true,\"entries\":[42]}";

    /** Creates a FIFO container over {@code framed}; returns its cref object as the wire writes it. */
    private static String createFifo(Framed framed) throws IOException {
        Answer created = framed.exchange("create", "{\"spec\":{\"order\":\"fifo\"}}");
        return created.body().substring(created.body().indexOf('{', 1), created.body().lastIndexOf('}'));
    }

    /** Sends take {@code call} of one entry, which will wait (5 s at most), without reading its answer. */
    private static void sendTake(Framed taker, String cref, String call) throws IOException {
        taker.send("take", null, null, "{\"container\":" + cref
                + ",\"timeout\":5000,\"selectors\":[{\"order\":\"fifo\"}],\"call\":\"" + call + "\"}");
    }

    /** Writes the entry 42 over {@code writer} as call {@code call}. */
    private static void write42(Framed writer, String cref, String call) throws IOException {
        assertEquals(200, writer.exchange("write", "{\"container\":" + cref
                + ",\"timeout\":0,\"items\":[{\"entry\":42}],\"call\":\"" + call + "\"}").status());
    }

    @Test
    void aClientThatClosesItsConnectionWhileItsTakeWaitsIsNoticedAtOnce() throws Exception {
        try (SpaceServer server = start(null)) {
            Framed taker = new Framed(server.uri());
            Answer created = taker.exchange("create", "{\"spec\":{\"order\":\"fifo\"}}");
            String cref = created.body().substring(created.body().indexOf('{', 1), created.body().lastIndexOf('}'));
            taker.send("take", null, null, "{\"container\":" + cref
                    + ",\"timeout\":15000,\"selectors\":[{\"order\":\"fifo\"}],\"call\":\"t1\"}");
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (server.space().describeContainer(internalRef(server, cref)).blocked() < 1) {
                assertTrue(System.nanoTime() < deadline, "the take never waited");
                Thread.sleep(5);
            }
            assertEquals(1, server.connectionKinds().stream().filter("FrameConnection"::equals).count());
            taker.close();
            // the connection is closed well before the take's 15 s run out (its count against the limits with it)
            deadline = System.nanoTime() + 3_000_000_000L;
            while (server.connectionKinds().contains("FrameConnection")) {
                assertTrue(System.nanoTime() < deadline, "still open: " + server.connectionKinds());
                Thread.sleep(10);
            }
        }
    }

    /** The container a cref object of the wire names, as the server's own space knows it. */
    private static robotworld.space.ContainerRef internalRef(SpaceServer server, String crefJson) {
        String id = crefJson.replaceAll(".*\"cref\":\"([^\"]+)\".*", "$1");
        return new robotworld.space.ContainerRef(server.space().spaceUri(), id);
    }

    @Test
    void aFrameThatCannotBeReadGets400AndItsConnectionClosesWhileTheServerKeepsServing() throws Exception {
        try (SpaceServer server = start(null)) {
            try (Framed framed = new Framed(server.uri())) {
                assertTrue(framed.upgraded(), framed.upgradeAnswer);
                // says 9 bytes, of which the name takes 200: its fields do not fit
                framed.sendRaw(ByteBuffer.allocate(13).putInt(9).put((byte) 200).put(new byte[8]).array());
                Answer answer = framed.receive();
                assertEquals(400, answer.status(), answer.body());
                assertTrue(answer.body().contains("shorter than its fields"), answer.body());
                assertEquals(Frames.CLOSING, answer.flags() & Frames.CLOSING);
                assertTrue(framed.closedByServer());
            }
            try (Framed framed = new Framed(server.uri())) {
                // an operation name that is not printable text
                framed.sendRaw(ByteBuffer.allocate(12).putInt(8).put((byte) 3).put(new byte[] {1, 2, 3})
                        .putShort((short) 0).putShort((short) 0).array());
                assertEquals(400, framed.receive().status());
            }
            try (Framed framed = new Framed(server.uri())) {
                assertEquals(200, framed.exchange("lookupOrCreate", "{\"spec\":{\"name\":\"after\"}}").status());
            }
        }
    }

    @Test
    void anOversizedFrameIsRefusedWith413BeforeItsBodyIsSent() throws Exception {
        try (SpaceServer server = start(null); Framed framed = new Framed(server.uri())) {
            framed.sendRaw(ByteBuffer.allocate(4).putInt(Integer.MAX_VALUE).array());
            Answer answer = framed.receive();
            assertEquals(413, answer.status(), answer.body());
            assertTrue(framed.closedByServer());
        }
    }

    @Test
    void everyFrameNeedsTheTokenOfAServerThatHasOne() throws Exception {
        try (SpaceServer server = start("s3cret with spaces"); Framed framed = new Framed(server.uri())) {
            framed.send("lookupOrCreate", null, null, "{\"spec\":{\"name\":\"q\"}}");
            Answer without = framed.receive();
            assertEquals(401, without.status(), without.body());
            framed.send("lookupOrCreate", "wrong", null, "{\"spec\":{\"name\":\"q\"}}");
            assertEquals(401, framed.receive().status());
            framed.send("lookupOrCreate", "s3cret with spaces", null, "{\"spec\":{\"name\":\"q\"}}");
            Answer with = framed.receive();
            assertEquals(200, with.status(), with.body());
        }
    }

    @Test
    void aRemoteSpaceCarriesItsOperationsAsFramesOnceTheServerOffersThem() throws Exception {
        try (SpaceServer server = start(null); RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO));
            client.write(queue, Timeout.TRY_ONCE, Entry.of("x"));
            assertEquals(List.of(Entry.of("x")), client.take(queue, Timeout.ofMillis(1_000),
                    robotworld.space.Selector.fifo(1)));
            assertTrue(server.connectionKinds().contains("FrameConnection"), "connections: " + server.connectionKinds());
        }
    }

    @Test
    void takesWaitingWithoutAThreadGoAsFramesToo() throws Exception {
        try (SpaceServer server = start(null); RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO));
            List<java.util.concurrent.CompletableFuture<Object>> outcomes = new java.util.ArrayList<>();
            for (int i = 0; i < 3; i++) {
                java.util.concurrent.CompletableFuture<Object> outcome = new java.util.concurrent.CompletableFuture<>();
                outcomes.add(outcome);
                client.takeLater(queue, Timeout.ofMillis(10_000), new robotworld.space.Selector[0],
                        robotworld.testsupport.Completions.into(outcome, entries -> entries));
            }
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (client.describeContainer(queue).blocked() < 3 && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            long framedConnections = server.connectionKinds().stream().filter("FrameConnection"::equals).count();
            assertTrue(framedConnections >= 3, "each waiting take on a framed connection: " + server.connectionKinds());
            for (int i = 0; i < 3; i++) {
                client.write(queue, Timeout.TRY_ONCE, Entry.of(i));
            }
            java.util.Set<Object> received = new java.util.HashSet<>();
            for (java.util.concurrent.CompletableFuture<Object> outcome : outcomes) {
                Object result = outcome.get(10, java.util.concurrent.TimeUnit.SECONDS);
                assertTrue(result instanceof List<?>, "a take failed: " + result);
                received.add(((List<?>) result).get(0));
            }
            assertEquals(java.util.Set.of(Entry.of(0), Entry.of(1), Entry.of(2)), received);
        }
    }

    @Test
    void behindAProxyThatDropsUpgradesAClientStaysOnHttpAndLosesNoCall() throws Exception {
        try (SpaceServer server = start(null);
             robotworld.testsupport.UpgradeStrippingProxy proxy =
                     new robotworld.testsupport.UpgradeStrippingProxy(server.port())) {
            URI served = server.uri();
            URI proxied = new URI(served.getScheme(), null, served.getHost(), proxy.port(), served.getPath(), null,
                    null);
            try (RemoteSpace direct = RemoteSpace.open(server.uri(), RemoteSpace.Options.defaults().frames(false));
                 RemoteSpace client = RemoteSpace.open(proxied)) {
                ContainerRef queue = direct.createContainer(ContainerSpec.of(Order.FIFO));
                // the client's first operation is a wait without a thread: it sends its upgrade and its first frame
                // in one write; refused, the frame goes again over HTTP
                java.util.concurrent.CompletableFuture<Object> later = new java.util.concurrent.CompletableFuture<>();
                client.takeLater(queue, Timeout.ofMillis(10_000), new robotworld.space.Selector[0],
                        robotworld.testsupport.Completions.into(later, entries -> entries));
                long deadline = System.nanoTime() + 10_000_000_000L;
                while (direct.describeContainer(queue).blocked() < 1 && System.nanoTime() < deadline) {
                    Thread.sleep(10);
                }
                assertEquals(1, direct.describeContainer(queue).blocked(), "the take waits on the server");
                assertTrue(proxy.upgradesStripped() >= 1, "the take asked for frames");
                for (int i = 0; i < 20; i++) {
                    client.write(queue, Timeout.TRY_ONCE, Entry.of(i));
                }
                assertEquals(List.of(Entry.of(0)), later.get(10, java.util.concurrent.TimeUnit.SECONDS));
                for (int i = 1; i < 20; i++) {
                    assertEquals(List.of(Entry.of(i)), client.take(queue, Timeout.ofMillis(1_000),
                            robotworld.space.Selector.fifo(1)), "each write once, in order");
                }
                org.junit.jupiter.api.Assertions.assertThrows(robotworld.space.SpaceTimeoutException.class,
                        () -> client.take(queue, Timeout.TRY_ONCE, robotworld.space.Selector.fifo(1)),
                        "nothing written twice");
            }
            assertTrue(proxy.upgradesStripped() <= 2, "and stopped asking once refused: " + proxy.upgradesStripped());
            assertTrue(!server.connectionKinds().contains("FrameConnection"), "connections: "
                    + server.connectionKinds());
        }
    }
}
