package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.EntryType;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Template;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/** Template selection (arity, type, value, wildcard, nesting, count), its order, and chained selectors. */
public abstract class TemplateContract extends SpaceContract {

    private static final Tuple A = Tuple.of(4, 7, "test");
    private static final Tuple B = Tuple.of(5, "test", "x");
    private static final Tuple C = Tuple.of(6, 7, "other");
    private static final Tuple D = Tuple.of(8, 9, "test", 1);
    private static final Tuple E = Tuple.of(9, Tuple.of("inner", 3));

    private ContainerRef filled(Order order) {
        ContainerRef ref = container(order);
        for (Entry entry : List.of(A, B, C, D, E, num(7), Entry.of("test"))) {
            space.write(ref, Timeout.TRY_ONCE, entry);
        }
        return ref;
    }

    private List<Entry> all(ContainerRef ref, Template template) {
        return space.read(ref, Timeout.TRY_ONCE, Selector.template(template, Selector.ALL));
    }

    @Test
    void thesisExampleIntegerExactStringWildcard() {
        ContainerRef ref = filled(Order.FIFO);
        Template template = Template.tuple(EntryType.INTEGER, "test", Template.ANY);
        assertEquals(List.of(B), all(ref, template));
    }

    @Test
    void arityMustMatch() {
        ContainerRef ref = filled(Order.FIFO);
        assertEquals(List.of(A, B, C), all(ref, Template.tuple(Template.ANY, Template.ANY, Template.ANY)));
        assertEquals(List.of(D), all(ref, Template.tuple(Template.ANY, Template.ANY, Template.ANY, Template.ANY)));
        assertEquals(List.of(), all(ref, Template.tuple()));
    }

    @Test
    void fieldTypesAndExactValues() {
        ContainerRef ref = filled(Order.FIFO);
        assertEquals(List.of(A, C), all(ref, Template.tuple(EntryType.INTEGER, 7, EntryType.STRING)));
        assertEquals(List.of(A), all(ref, Template.tuple(4, EntryType.INTEGER, "test")));
        assertEquals(List.of(E), all(ref, Template.tuple(EntryType.INTEGER, EntryType.TUPLE)));
    }

    @Test
    void nestedTupleTemplates() {
        ContainerRef ref = filled(Order.FIFO);
        assertEquals(List.of(E), all(ref, Template.tuple(Template.ANY, Template.tuple("inner", EntryType.INTEGER))));
        assertEquals(List.of(), all(ref, Template.tuple(Template.ANY, Template.tuple("inner", EntryType.STRING))));
    }

    @Test
    void templatesForPlainEntries() {
        ContainerRef ref = filled(Order.FIFO);
        assertEquals(List.of(num(7)), all(ref, Template.type(EntryType.INTEGER)));
        assertEquals(List.of(Entry.of("test")), all(ref, Template.value(Entry.of("test"))));
        assertEquals(7, all(ref, Template.ANY).size());
    }

    @Test
    void defaultCountIsOneAndResultsFollowTheBaseOrder() {
        Template threeFields = Template.tuple(Template.ANY, Template.ANY, Template.ANY);
        ContainerRef fifo = filled(Order.FIFO);
        assertEquals(List.of(A), space.read(fifo, Timeout.TRY_ONCE, Selector.template(threeFields)));
        assertEquals(List.of(A, B), space.read(fifo, Timeout.TRY_ONCE, Selector.template(threeFields, 2)));
        ContainerRef lifo = filled(Order.LIFO);
        assertEquals(List.of(C), space.read(lifo, Timeout.TRY_ONCE, Selector.template(threeFields)));
        assertEquals(List.of(C, B, A), all(lifo, threeFields));
    }

    @Test
    void templateOrderOnLruFollowsUse() {
        ContainerRef ref = filled(Order.LRU);
        Template threeFields = Template.tuple(Template.ANY, Template.ANY, Template.ANY);
        space.read(ref, Timeout.TRY_ONCE, Selector.template(Template.value(A)));
        assertEquals(List.of(B, C, A), all(ref, threeFields));
    }

    @Test
    void takeByTemplateRemovesOnlyMatches() {
        ContainerRef ref = filled(Order.FIFO);
        assertEquals(List.of(A, C), space.take(ref, Timeout.TRY_ONCE,
                Selector.template(Template.tuple(EntryType.INTEGER, 7, Template.ANY), Selector.ALL)));
        assertSize(ref, 5);
        assertEquals(List.of(), all(ref, Template.tuple(EntryType.INTEGER, 7, Template.ANY)));
    }

    @Test
    void notEnoughMatchesWaitsUntilWritten() throws Exception {
        ContainerRef ref = filled(Order.FIFO);
        Template request = Template.tuple("host-b", EntryType.INTEGER);
        assertThrows(SpaceTimeoutException.class, () -> space.take(ref, Timeout.TRY_ONCE, Selector.template(request)));
        Future<List<Entry>> taker = async(() -> space.take(ref, Timeout.INFINITE, Selector.template(request, 2)));
        awaitBlocked(ref, 1);
        space.write(ref, Timeout.TRY_ONCE, Tuple.of("host-b", 1), Tuple.of("host-a", 2));
        space.write(ref, Timeout.TRY_ONCE, Tuple.of("host-b", 3));
        assertEquals(List.of(Tuple.of("host-b", 1), Tuple.of("host-b", 3)), result(taker));
    }

    @Test
    void chainedSelectorsRefineEachOther() {
        ContainerRef ref = filled(Order.FIFO);
        Template threeFields = Template.tuple(Template.ANY, Template.ANY, Template.ANY);
        assertEquals(List.of(C, B), space.read(ref, Timeout.TRY_ONCE,
                Selector.template(threeFields, Selector.ALL), Selector.lifo(2)));
        assertEquals(List.of(C), space.read(ref, Timeout.TRY_ONCE,
                Selector.fifo(Selector.ALL), Selector.template(Template.tuple(6, Template.ANY, Template.ANY))));
        assertThrows(SpaceTimeoutException.class, () -> space.read(ref, Timeout.TRY_ONCE,
                Selector.template(threeFields, Selector.ALL), Selector.fifo(4)));
    }

    @Test
    void chainsWithViews() {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).withKeyView().withVectorView());
        space.write(ref, Timeout.TRY_ONCE, List.of(Item.keyed("a", Tuple.of("a", 1)), Item.keyed("b", Tuple.of("b", 2)),
                Item.of(Tuple.of("c", 3))));
        assertEquals(List.of(Tuple.of("b", 2)), space.read(ref, Timeout.TRY_ONCE,
                Selector.vector(0, Selector.ALL), Selector.key("b")));
        assertEquals(List.of(Tuple.of("b", 2), Tuple.of("c", 3)), space.read(ref, Timeout.TRY_ONCE,
                Selector.fifo(Selector.ALL), Selector.vector(1, 2)));
        assertEquals(List.of(Tuple.of("c", 3)), space.read(ref, Timeout.TRY_ONCE,
                Selector.template(Template.tuple(EntryType.STRING, 3)), Selector.vector(0, Selector.ALL)));
    }
}
