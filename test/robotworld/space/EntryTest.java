package robotworld.space;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** Entry values, templates and the validation of selectors, items, specs and timeouts. */
class EntryTest {

    @Test
    void entriesAreValuesComparedByContent() {
        assertEquals(Entry.of(4), new IntEntry(4));
        assertEquals(Entry.of("a").hashCode(), new StringEntry("a").hashCode());
        assertEquals(Tuple.of(4, "x", Tuple.of(1)), Tuple.of(Entry.of(4), Entry.of("x"), Tuple.of(Entry.of(1))));
        assertNotEquals(Tuple.of(4, 7), Tuple.of(7, 4));
        URI space = URI.create("embedded:s");
        assertEquals(new ContainerRef(space, "c1"), new ContainerRef(space, "c1"));
        assertNotEquals(new ContainerRef(space, "c1"), new ContainerRef(URI.create("embedded:t"), "c1"));
    }

    @Test
    void printedFormIsReadable() {
        assertEquals("<4, 7, \"test\">", Tuple.of(4, 7, "test").toString());
        assertEquals("<1, <\"a\\\"b\">>", Tuple.of(1, Tuple.of("a\"b")).toString());
        assertEquals("cref(embedded:s#c1)", new ContainerRef(URI.create("embedded:s"), "c1").toString());
    }

    @Test
    void tuplesAreImmutable() {
        List<Entry> fields = new ArrayList<>(List.of(Entry.of(1)));
        Tuple tuple = new Tuple(fields);
        fields.add(Entry.of(2));
        assertEquals(1, tuple.arity());
        assertThrows(UnsupportedOperationException.class, () -> tuple.fields().add(Entry.of(3)));
    }

    @Test
    void typedAccessors() {
        URI space = URI.create("embedded:s");
        Tuple tuple = Tuple.of(Entry.of(5), Entry.of("s"), Tuple.of(1), new ContainerRef(space, "c"));
        assertEquals(5, tuple.longAt(0));
        assertEquals("s", tuple.stringAt(1));
        assertEquals(Tuple.of(1), tuple.tupleAt(2));
        assertEquals("c", tuple.crefAt(3).id());
        assertThrows(ClassCastException.class, () -> tuple.stringAt(0));
    }

    @Test
    void conversionFromJavaValues() {
        assertEquals(Entry.of(3), Entry.from(3));
        assertEquals(Entry.of(3), Entry.from((short) 3));
        assertEquals(Tuple.of(1, "a"), Entry.from(List.of(1, "a")));
        assertThrows(IllegalArgumentException.class, () -> Entry.from(1.5));
        assertThrows(IllegalArgumentException.class, () -> Entry.from(null));
        assertThrows(NullPointerException.class, () -> new StringEntry(null));
    }

    @Test
    void templateMatching() {
        Template thesis = Template.tuple(EntryType.INTEGER, "test", Template.ANY);
        assertTrue(thesis.matches(Tuple.of(4, "test", 9)));
        assertTrue(thesis.matches(Tuple.of(4, "test", Tuple.of())));
        assertFalse(thesis.matches(Tuple.of(4, "test")), "arity");
        assertFalse(thesis.matches(Tuple.of("4", "test", 1)), "type");
        assertFalse(thesis.matches(Tuple.of(4, "Test", 1)), "value");
        assertFalse(thesis.matches(Entry.of(4)), "not a tuple");
        assertTrue(Template.ANY.matches(Entry.of("x")));
        assertEquals("<integer, \"test\", ?>", thesis.toString());
    }

    @Test
    void selectorCountsAreChecked() {
        assertThrows(IllegalArgumentException.class, () -> Selector.fifo(0));
        assertThrows(IllegalArgumentException.class, () -> Selector.template(Template.ANY, -2));
        assertThrows(IllegalArgumentException.class, () -> Selector.key("k", 2));
        assertThrows(IllegalArgumentException.class, () -> Selector.vector(-1));
        assertEquals(Selector.ALL, Selector.lru(Selector.ALL).count());
    }

    @Test
    void specsItemsAndTimeoutsAreChecked() {
        assertThrows(IllegalArgumentException.class, () -> ContainerSpec.defaults().bounded(0));
        assertThrows(IllegalArgumentException.class, () -> ContainerSpec.defaults().named(" "));
        assertEquals(Order.RANDOM, ContainerSpec.defaults().order());
        assertEquals(Uniqueness.BAG, ContainerSpec.defaults().uniqueness());
        assertFalse(ContainerSpec.defaults().isBounded());
        assertThrows(IllegalArgumentException.class, () -> Item.at(-1, Entry.of(1)));
        assertThrows(IllegalArgumentException.class, () -> Timeout.ofMillis(-2));
        assertTrue(Timeout.INFINITE.isInfinite());
        assertTrue(Timeout.TRY_ONCE.isTryOnce());
    }

    @Test
    void anyIncludesEveryOperation() {
        assertEquals(Operation.values().length, Operation.any().size());
        assertThrows(UnsupportedOperationException.class, () -> Operation.any().clear());
    }
}
