package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.EntryType;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Template;
import robotworld.space.Timeout;
import robotworld.space.Tuple;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.wire.BinaryWire;
import robotworld.space.wire.CrefMapping;
import robotworld.space.wire.Frames;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireFormatException;
import robotworld.space.wire.WireLimits;
import robotworld.space.wire.WireReader;
import robotworld.space.wire.WireWriter;
import robotworld.testsupport.LinkFaultProxy;

/**
 * The binary form of the hot operations' bodies: it reads as the same fields and values as JSON, it is held to the
 * same limits, anything malformed in it is a clean 400 (never another failure), the server answers it in kind, and a
 * client uses it only where it may.
 */
class BinaryBodiesTest {

    private static final URI SPACE = URI.create("http://127.0.0.1:9876/space");
    private static final WireLimits LIMITS = WireLimits.DEFAULTS;
    private static final WireContext WIRE = WireContext.of(LIMITS, CrefMapping.IDENTITY);
    private static final ContainerRef REQUESTS = new ContainerRef(SPACE, "c17-2kf9q1x0");
    private static final ContainerRef ANSWERS = new ContainerRef(SPACE, "c18-2kf9q1x0");

    /** A writeThenTake with every kind of value the binary form carries. */
    private static void everyKindOfValue(WireWriter out) {
        out.startObject();
        out.cref("container", REQUESTS).field("timeout", -1L);
        out.items(List.of(
                Item.of(Tuple.of("A", 0, Long.MIN_VALUE, Long.MAX_VALUE, -1, "ünïcødé ✓ 🤖", "")),
                Item.keyed("key-1", new Tuple(List.of(Tuple.of(Tuple.of(1), Tuple.of()), ANSWERS))),
                Item.at(7, Entry.of(42)),
                new Item(Tuple.of("both"), "k", 3)));
        out.field("call", "f5cf5b83066e6c04:4");
        out.field("take").startObject().cref("container", ANSWERS).selectors(new Selector[] {
            Selector.key("A"), Selector.order(Order.FIFO, 3), Selector.order(Order.RANDOM, Selector.ALL),
            Selector.order(Order.LIFO, 1), Selector.order(Order.LRU, 2), Selector.vector(5, 2),
            Selector.template(Template.tuple(EntryType.INTEGER, "test", Template.ANY), Selector.ALL),
            Selector.template(Template.type(EntryType.CREF), 1),
            Selector.template(Template.value(Tuple.of("x", 1)), 4),
            Selector.template(new Template.TupleOf(List.of(Template.type(EntryType.TUPLE),
                    Template.type(EntryType.STRING))), 1)})
                .field("call", "f5cf5b83066e6c04:4.t").endObject();
        out.endObject();
    }

    private static byte[] json(Consumer<WireWriter> message) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (WireWriter out = WIRE.writer(bytes)) {
            message.accept(out);
        }
        return bytes.toByteArray();
    }

    private static byte[] binary(Consumer<WireWriter> message) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (WireWriter out = WireWriter.binary(CrefMapping.IDENTITY, bytes)) {
            message.accept(out);
        }
        return bytes.toByteArray();
    }

    private static RequestFields request(byte[] body) {
        try (WireReader in = WIRE.reader(body, 0, body.length)) {
            return RequestFields.parse(in, 1_000);
        }
    }

    @Test
    void aRequestReadsAsTheSameFieldsInBothForms() {
        byte[] json = json(BinaryBodiesTest::everyKindOfValue);
        byte[] binary = binary(BinaryBodiesTest::everyKindOfValue);
        assertEquals(BinaryWire.MARKER, binary[0]);
        assertTrue(binary.length < json.length / 2, binary.length + " bytes against JSON's " + json.length);

        RequestFields fromJson = request(json);
        RequestFields fromBinary = request(binary);
        assertEquals(fromJson.container, fromBinary.container);
        assertEquals(fromJson.timeout, fromBinary.timeout);
        assertEquals(fromJson.items, fromBinary.items);
        assertEquals(fromJson.call, fromBinary.call);
        assertEquals(fromJson.take.container, fromBinary.take.container);
        assertEquals(List.of(fromJson.take.selectors), List.of(fromBinary.take.selectors));
        assertEquals(fromJson.take.call, fromBinary.take.call);
        assertEquals(Long.MIN_VALUE, ((Tuple) fromBinary.items.get(0).entry()).longAt(2));
        assertEquals("ünïcødé ✓ 🤖", ((Tuple) fromBinary.items.get(0).entry()).stringAt(5));
    }

    @Test
    void anAnswerReadsAsTheSameFieldsInBothForms() {
        Consumer<WireWriter> answer = out -> out.startObject().entries("displaced", List.of(Tuple.of("old", 1)))
                .field("written", true).field("ack", true).entries("entries", List.of(Tuple.of("A", 3), REQUESTS))
                .field("more", false).field("count", 123_456_789_012L).endObject();
        assertEquals(readAll(json(answer)), readAll(binary(answer)));
        assertEquals(List.of("displaced", "written", "ack", "entries", "more", "count"),
                readAll(binary(answer)).stream().map(field -> field.get(0)).toList());
    }

    private static List<List<Object>> readAll(byte[] body) {
        List<List<Object>> fields = new ArrayList<>();
        try (WireReader in = WIRE.reader(body, 0, body.length)) {
            in.startObject();
            String field;
            while ((field = in.nextField()) != null) {
                Object value = switch (field) {
                    case "entries", "displaced" -> in.readEntries(field);
                    case "written", "ack", "more" -> in.readBoolean(field);
                    case "count" -> in.readLong(field);
                    default -> throw new AssertionError(field);
                };
                fields.add(List.of(field, value));
            }
            in.end();
        }
        return fields;
    }

    @Test
    void theExampleOfTheWireDocumentIsWhatAWriterWrites() {
        byte[] take = binary(out -> out.startObject().cref("container", REQUESTS).field("timeout", 1_000L)
                .selectors(new Selector[] {Selector.fifo()}).field("call", "t-2").endObject());
        ByteArrayOutputStream expected = new ByteArrayOutputStream();
        expected.writeBytes(new byte[] {(byte) 0xB1, 0x01, 0x0C});
        expected.writeBytes("c17-2kf9q1x0".getBytes(StandardCharsets.US_ASCII));
        expected.write(0x1B);
        expected.writeBytes("http://127.0.0.1:9876/space".getBytes(StandardCharsets.US_ASCII));
        expected.writeBytes(new byte[] {0x02, (byte) 0xD0, 0x0F, 0x03, 0x01, 0x01, 0x01, 0x01, 0x05, 0x03});
        expected.writeBytes("t-2".getBytes(StandardCharsets.US_ASCII));
        expected.write(0x00);
        assertArrayEquals(expected.toByteArray(), take);
    }

    @Test
    void everyTruncatedMessageIsAFormatError() {
        byte[] whole = binary(BinaryBodiesTest::everyKindOfValue);
        for (int length = 1; length < whole.length; length++) {
            byte[] part = Arrays.copyOf(whole, length);
            assertThrows(WireFormatException.class, () -> request(part), "cut at " + part.length);
        }
        byte[] longer = Arrays.copyOf(whole, whole.length + 1);
        assertTrue(assertThrows(WireFormatException.class, () -> request(longer)).getMessage()
                .contains("after the message"));
    }

    @Test
    void damagedAndRandomMessagesAreFormatErrorsAndNothingElse() {
        Random random = new Random(20261129);
        byte[] whole = binary(BinaryBodiesTest::everyKindOfValue);
        int read = 0;
        for (int i = 0; i < 20_000; i++) {
            byte[] damaged;
            if (i % 2 == 0) {
                damaged = whole.clone();
                for (int flips = 1 + random.nextInt(3); flips > 0; flips--) {
                    damaged[1 + random.nextInt(damaged.length - 1)] = (byte) random.nextInt(256);
                }
            } else {
                damaged = new byte[1 + random.nextInt(64)];
                random.nextBytes(damaged);
                damaged[0] = BinaryWire.MARKER;
            }
            try {
                request(damaged);
                read++;
            } catch (WireFormatException expected) {
                // the only failure allowed
            }
        }
        assertTrue(read < 20_000, "some damage must be noticed");
    }

    @Test
    void theLimitsOfJsonHoldInTheBinaryFormToo() {
        WireLimits tight = new WireLimits(1 << 20, 3, 10, 5, 2, 2);
        WireContext wire = WireContext.of(tight, CrefMapping.IDENTITY);
        List<Consumer<WireWriter>> tooMuch = List.of(
                out -> out.startObject().items(List.of(Item.of(Tuple.of("eleven chars")))).endObject(),
                out -> out.startObject().items(List.of(Item.of(Tuple.of(1)), Item.of(Tuple.of(2)),
                        Item.of(Tuple.of(3)))).endObject(),
                out -> out.startObject().items(List.of(Item.of(Tuple.of(Tuple.of(Tuple.of(Tuple.of(1)))))))
                        .endObject(),
                out -> out.startObject().selectors(new Selector[] {Selector.order(Order.FIFO, 6)}).endObject(),
                out -> out.startObject().selectors(new Selector[] {Selector.key("a"), Selector.key("b"),
                    Selector.key("c")}).endObject(),
                out -> out.startObject().field("timeout", -2L).endObject());
        for (Consumer<WireWriter> message : tooMuch) {
            byte[] body = binary(message);
            assertThrows(WireFormatException.class, () -> {
                try (WireReader in = wire.reader(body, 0, body.length)) {
                    RequestFields.parse(in, 10);
                }
            });
        }
        byte[] twice = {BinaryWire.MARKER, 2, 0, 2, 0, 0}; // timeout, timeout
        assertTrue(assertThrows(WireFormatException.class, () -> request(twice)).getMessage().contains("twice"));
        byte[] unknown = {BinaryWire.MARKER, 99, 0};
        assertThrows(WireFormatException.class, () -> request(unknown));
        byte[] notUtf8 = {BinaryWire.MARKER, 5, 2, (byte) 0xC3, 0x28, 0};
        assertTrue(assertThrows(WireFormatException.class, () -> request(notUtf8)).getMessage().contains("UTF-8"));
        byte[] hugeCount = {BinaryWire.MARKER, 4, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, 0x0F, 0};
        assertThrows(WireFormatException.class, () -> request(hugeCount));
        byte[] sixtyFiveBits = {BinaryWire.MARKER, 2, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0x7F, 0};
        assertThrows(WireFormatException.class, () -> request(sixtyFiveBits));
        // fields the binary form does not carry cannot be written in it
        assertThrows(IllegalStateException.class, () -> binary(out -> out.startObject()
                .spec("spec", ContainerSpec.of(Order.FIFO))));
        assertThrows(IllegalStateException.class, () -> binary(out -> out.startObject().field("outcome", "x")));
    }

    // ---- over the wire ----

    private static byte[] frame(String operation, byte[] body) {
        byte[] name = operation.getBytes(StandardCharsets.US_ASCII);
        int length = 1 + name.length + 2 + 2 + body.length;
        return ByteBuffer.allocate(4 + length).putInt(length).put((byte) name.length).put(name).putShort((short) 0)
                .putShort((short) 0).put(body).array();
    }

    private record Answer(int status, byte[] body) {
        String text() {
            return new String(body, StandardCharsets.UTF_8);
        }
    }

    private static Answer receive(DataInputStream in) throws IOException {
        int length = in.readInt();
        int status = in.readUnsignedShort();
        in.readUnsignedByte();
        byte[] body = new byte[length - 3];
        in.readFully(body);
        return new Answer(status, body);
    }

    @Test
    void theServerAnswersABinaryRequestInKindAndRefusesOneItCannotCarryWithAReason() throws Exception {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
             Socket socket = new Socket()) {
            ContainerRef queue = server.space().createContainer(ContainerSpec.of(Order.FIFO));
            ContainerRef wire = new ContainerRef(server.uri(), queue.id()); // as a remote client names it
            socket.connect(new InetSocketAddress(server.uri().getHost(), server.port()), 2_000);
            socket.setSoTimeout(5_000);
            OutputStream out = socket.getOutputStream();
            DataInputStream in = new DataInputStream(socket.getInputStream());
            out.write(("GET " + server.uri().getPath() + " HTTP/1.1\r\nHost: test\r\nConnection: Upgrade\r\nUpgrade: "
                    + Frames.PROTOCOL + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
            String head = "";
            while (!head.endsWith("\r\n\r\n")) {
                head += (char) in.read();
            }
            assertTrue(head.startsWith("HTTP/1.1 101 "), head);

            out.write(frame("write", binary(w -> w.startObject().cref("container", wire).field("timeout", 0L)
                    .items(List.of(Item.of(Tuple.of("hello", 1)))).field("call", "t-1").endObject())));
            Answer written = receive(in);
            assertEquals(200, written.status(), written.text());
            assertEquals(BinaryWire.MARKER, written.body()[0]);

            out.write(frame("take", binary(w -> w.startObject().cref("container", wire).field("timeout", 1_000L)
                    .selectors(new Selector[] {Selector.fifo()}).field("call", "t-2").endObject())));
            Answer taken = receive(in);
            assertEquals(200, taken.status(), taken.text());
            List<List<Object>> fields = readAll(taken.body());
            assertTrue(fields.contains(List.of("entries", List.of(Tuple.of("hello", 1)))), fields.toString());

            // an operation outside the binary form: a JSON error that says what to do
            out.write(frame("cancel", binary(w -> w.startObject().field("call", "t-2").endObject())));
            Answer refused = receive(in);
            assertEquals(400, refused.status());
            assertTrue(refused.text().contains("send it as JSON"), refused.text());
            // damaged: 400 as well, and the connection goes on serving
            out.write(frame("take", new byte[] {BinaryWire.MARKER, 1, 9}));
            assertEquals(400, receive(in).status());
            out.write(frame("describe", ("{\"container\":{\"cref\":\"" + queue.id() + "\",\"space\":\""
                    + server.uri() + "\"}}").getBytes(StandardCharsets.UTF_8)));
            assertEquals(200, receive(in).status());

            // over plain HTTP a binary body is refused
            RawHttp.Answer http = RawHttp.send(server.uri(), "POST " + server.uri().getPath()
                    + "/take HTTP/1.1\r\nContent-Type: application/json\r\nContent-Length: 3\r\n",
                    new byte[] {BinaryWire.MARKER, 0, 0});
            assertEquals(400, http.status(), http.body());
            assertTrue(http.body().contains("only in a frame"), http.body());
        }
    }

    @Test
    void aRemoteSpaceSendsTheHotOperationsInBinaryAndTheRestAsJsonUnlessToldOtherwise() throws Exception {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100))) {
            assertEquals(List.of("create:JSON", "write:binary", "take:binary", "writeThenTake:binary",
                    "describe:JSON"), bodiesSent(server, RemoteSpace.Options.defaults()));
            assertEquals(List.of("create:JSON", "write:JSON", "take:JSON", "writeThenTake:JSON", "describe:JSON"),
                    bodiesSent(server, RemoteSpace.Options.defaults().binary(false)));
        }
    }

    /** The operations one client sent in frames (after its description and upgrade as HTTP), each with its form. */
    private static List<String> bodiesSent(SpaceServer server, RemoteSpace.Options options) throws Exception {
        try (LinkFaultProxy proxy = capturing(new LinkFaultProxy(server.port()));
             RemoteSpace client = RemoteSpace.open(URI.create("http://127.0.0.1:"
                     + proxy.portName().substring(proxy.portName().lastIndexOf(':') + 1) + server.uri().getPath()),
                     options)) {
            ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO).withKeyView());
            client.write(queue, Timeout.TRY_ONCE, Tuple.of("x", 1));
            assertEquals(List.of(Tuple.of("x", 1)), client.take(queue, Timeout.ofMillis(2_000)));
            client.writeThenTake(queue, List.of(Item.keyed("k", Tuple.of("y"))), queue, Timeout.ofMillis(2_000),
                    Selector.key("k"));
            client.describeContainer(queue);
            // confirmations sent on their own, if any, are not what this is about
            return framesIn(proxy.clientBytes()).stream().filter(sent -> !sent.startsWith("ack:")).toList();
        }
    }

    private static LinkFaultProxy capturing(LinkFaultProxy proxy) {
        proxy.captureClientBytes();
        return proxy;
    }

    private static List<String> framesIn(byte[] stream) {
        String text = new String(stream, StandardCharsets.ISO_8859_1);
        String upgrade = "Upgrade: " + Frames.PROTOCOL + "\r\n\r\n";
        int at = text.indexOf(upgrade);
        assertTrue(at >= 0, "no upgrade to frames was sent");
        ByteBuffer frames = ByteBuffer.wrap(stream, at + upgrade.length(), stream.length - at - upgrade.length());
        List<String> found = new ArrayList<>();
        while (frames.remaining() >= 4) {
            int length = frames.getInt();
            int end = frames.position() + length;
            byte[] name = new byte[Byte.toUnsignedInt(frames.get())];
            frames.get(name);
            int token = frames.getShort();
            frames.position(frames.position() + token);
            int confirmations = frames.getShort();
            frames.position(frames.position() + confirmations);
            boolean binary = frames.get() == BinaryWire.MARKER;
            frames.position(end);
            found.add(new String(name, StandardCharsets.US_ASCII) + (binary ? ":binary" : ":JSON"));
        }
        assertNull(frames.hasRemaining() ? "left over" : null);
        return found;
    }
}
