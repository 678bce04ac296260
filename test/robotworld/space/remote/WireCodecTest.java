package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.EntryType;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Template;
import robotworld.space.Tuple;
import robotworld.space.wire.CrefMapping;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireFormatException;
import robotworld.space.wire.WireLimits;
import robotworld.space.wire.WireReader;
import robotworld.space.wire.WireWriter;

/** The typed JSON encoding of entries, templates, selectors, items and specs, and its limits. */
class WireCodecTest {

    private static final URI SPACE = URI.create("http://127.0.0.1:9876/space");
    private final WireContext wire = WireContext.of(WireLimits.DEFAULTS, CrefMapping.IDENTITY);

    private String encode(java.util.function.Consumer<WireWriter> body) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (WireWriter out = wire.writer(bytes)) {
            out.startObject();
            body.accept(out);
            out.endObject();
        }
        return bytes.toString(StandardCharsets.UTF_8);
    }

    private WireReader reader(String json) {
        byte[] bytes = json.getBytes(StandardCharsets.UTF_8);
        WireReader in = wire.reader(bytes, 0, bytes.length);
        in.startObject();
        in.nextField();
        return in;
    }

    @Test
    void eachEntryTypeHasItsOwnJsonType() {
        ContainerRef ref = new ContainerRef(SPACE, "c7");
        Tuple tuple = Tuple.of(Entry.of(Long.MIN_VALUE), Entry.of(Long.MAX_VALUE), Entry.of("h\u00e9llo \"\\\n"),
                ref, Tuple.of(), Tuple.of(Tuple.of(1, "x")));
        String json = encode(out -> out.field("e").entry(tuple));
        assertEquals("{\"e\":[-9223372036854775808,9223372036854775807,\"h\u00e9llo \\\"\\\\\\n\","
                + "{\"cref\":\"c7\",\"space\":\"http://127.0.0.1:9876/space\"},[],[[1,\"x\"]]]}", json);
        assertEquals(tuple, reader(json).readEntry());
        assertEquals(Entry.of("42"), reader("{\"e\":\"42\"}").readEntry(), "a string of digits stays a string");
        assertEquals(Entry.of(42), reader("{\"e\":42}").readEntry());
    }

    @Test
    void templatesSelectorsItemsAndSpecsRoundTrip() {
        Selector[] selectors = {Selector.fifo(3), Selector.key("host-a", Selector.ALL), Selector.vector(2, 4),
                Selector.template(Template.tuple(EntryType.INTEGER, "test", Template.ANY,
                        Template.tuple(Template.type(EntryType.CREF))), 1), Selector.order(Order.LRU, 1)};
        List<Item> items = List.of(Item.of(Entry.of(1)), Item.keyed("k", Entry.of("v")), Item.at(5, Tuple.of(1, 2)),
                Item.keyed("both", Entry.of(3)).atIndex(9));
        ContainerSpec spec = ContainerSpec.of(Order.LIFO).named("answers").bounded(5).set().withKeyView()
                .withVectorView();
        String json = encode(out -> out.selectors(selectors).items(items).spec("spec", spec)
                .spec("plain", ContainerSpec.defaults()));
        byte[] bytes = json.getBytes(StandardCharsets.UTF_8);
        try (WireReader in = wire.reader(bytes, 0, bytes.length)) {
            in.startObject();
            assertEquals("selectors", in.nextField());
            assertArrayEquals(selectors, in.readSelectors());
            assertEquals("items", in.nextField());
            assertEquals(items, in.readItems());
            assertEquals("spec", in.nextField());
            assertEquals(spec, in.readSpec());
            assertEquals("plain", in.nextField());
            assertEquals(ContainerSpec.defaults(), in.readSpec());
            assertEquals(null, in.nextField());
            in.end();
        }
    }

    @Test
    void crefsAreTranslatedBetweenTheSpaceAndItsPublicUri() {
        URI internal = URI.create("embedded:1234");
        WireContext server = WireContext.of(WireLimits.DEFAULTS, CrefMapping.between(internal, SPACE));
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (WireWriter out = server.writer(bytes)) {
            out.startObject().cref("c", new ContainerRef(internal, "c1")).endObject();
        }
        String json = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(json.contains(SPACE.toString()), json);
        byte[] raw = json.getBytes(StandardCharsets.UTF_8);
        try (WireReader in = server.reader(raw, 0, raw.length)) {
            in.startObject();
            in.nextField();
            assertEquals(new ContainerRef(internal, "c1"), in.readCref());
        }
    }

    @Test
    void limitsAreEnforcedWhileParsing() {
        String deep = "[".repeat(33) + "]".repeat(33);
        assertThrows(WireFormatException.class, () -> reader("{\"e\":" + deep + "}").readEntry());
        String fine = "[".repeat(32) + "]".repeat(32);
        reader("{\"e\":" + fine + "}").readEntry();
        assertThrows(WireFormatException.class,
                () -> reader("{\"s\":[{\"order\":\"fifo\",\"count\":100001}]}").readSelectors());
        assertThrows(WireFormatException.class,
                () -> reader("{\"s\":[{\"order\":\"fifo\",\"count\":0}]}").readSelectors());
        assertEquals(Selector.ALL, reader("{\"s\":[{\"order\":\"fifo\",\"count\":\"all\"}]}").readSelectors()[0].count());
        assertThrows(WireFormatException.class, () -> reader("{\"e\":\"" + "x".repeat(70_000) + "\"}").readEntry());
        assertThrows(WireFormatException.class, () -> reader("{\"e\":1e3}").readEntry());
        assertThrows(WireFormatException.class, () -> reader("{\"e\":18446744073709551616}").readEntry());
        assertThrows(WireFormatException.class, () -> reader("{\"t\":-2}").readTimeout());
        WireFormatException message = assertThrows(WireFormatException.class,
                () -> reader("{\"e\":{\"cref\":\"c1\"}}").readEntry());
        assertTrue(message.getMessage().contains("space"), message.getMessage());
    }

    @Test
    void aFieldNamedTwiceInOneObjectIsRefused() {
        WireReader top = reader("{\"t\":1,\"t\":2}");
        top.readTimeout();
        WireFormatException twice = assertThrows(WireFormatException.class, top::nextField);
        assertTrue(twice.getMessage().contains("'t' appears twice"), twice.getMessage());
        assertThrows(WireFormatException.class,
                () -> reader("{\"s\":[{\"order\":\"fifo\",\"order\":\"lifo\"}]}").readSelectors());
        assertThrows(WireFormatException.class,
                () -> reader("{\"e\":{\"cref\":\"c1\",\"space\":\"x\",\"cref\":\"c2\"}}").readEntry());
        // the same name in sibling objects, or in an object and one inside it, is two fields, not one twice
        assertEquals(2, reader("{\"s\":[{\"order\":\"fifo\"},{\"order\":\"lifo\"}]}").readSelectors().length);
        assertEquals(1, reader("{\"order\":[{\"order\":\"fifo\",\"count\":1}]}").readSelectors().length);
    }

    @Test
    void anObjectOfManyFieldsIsCheckedForTwiceNamedOnesToo() {
        // past its first few names an object's names go into a hash set: a name seen twice is found on either side
        StringBuilder many = new StringBuilder("{\"f0\":0");
        for (int i = 1; i < 50_000; i++) {
            many.append(",\"f").append(i).append("\":0");
        }
        assertEquals(50_000, skipAll(many + "}"));
        WireFormatException early = assertThrows(WireFormatException.class, () -> skipAll(many + ",\"f3\":1}"));
        assertTrue(early.getMessage().contains("'f3' appears twice"), early.getMessage());
        WireFormatException late = assertThrows(WireFormatException.class, () -> skipAll(many + ",\"f40000\":1}"));
        assertTrue(late.getMessage().contains("'f40000' appears twice"), late.getMessage());
    }

    /** Reads an object, skipping every value; returns how many fields it had. */
    private int skipAll(String json) {
        WireReader in = reader(json);
        int fields = 1;
        in.skipValue();
        while (in.nextField() != null) {
            in.skipValue();
            fields++;
        }
        return fields;
    }
}
