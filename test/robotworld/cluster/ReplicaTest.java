package robotworld.cluster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.AbstractMap;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeMap;
import java.util.UUID;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

import com.hazelcast.internal.serialization.InternalSerializationService;
import com.hazelcast.internal.serialization.impl.DefaultSerializationServiceBuilder;
import com.hazelcast.map.EntryProcessor;

import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.EntryType;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Template;
import robotworld.space.Tuple;

/**
 * A backup kept by replaying the owner's logged changes stays identical to the owner, whatever the calls: random
 * sequences of every kind of call on containers of every kind, each call and each change list sent through
 * Hazelcast's serialization as between members, the backup compared with the owner after every call, rebuilt now
 * and then from a full copy, and finally promoted to owner itself.
 */
class ReplicaTest {

    private static final InternalSerializationService SERIALIZATION = new DefaultSerializationServiceBuilder()
            .addDataSerializableFactory(ClusterSerialization.FACTORY_ID, new ClusterSerialization()).build();

    private static final UUID MEMBER_A = new UUID(1, 1);
    private static final UUID MEMBER_B = new UUID(2, 2);

    private final List<OpId> waiters = new ArrayList<>();
    private final List<OpId> subscribers = new ArrayList<>();
    private long counter;

    @ParameterizedTest
    @ValueSource(strings = {"FIFO", "LIFO", "LRU", "RANDOM"})
    void aBackupReplayingTheChangesEqualsTheOwner(String order) {
        for (long seed = 0; seed < 12; seed++) {
            Random random = new Random(seed * 31 + order.hashCode());
            ContainerSpec spec = ContainerSpec.of(Order.valueOf(order));
            if (random.nextBoolean()) {
                spec = spec.withKeyView();
            }
            if (random.nextBoolean()) {
                spec = spec.withVectorView();
            }
            if (random.nextInt(3) == 0) {
                spec = spec.set();
            }
            if (random.nextBoolean()) {
                spec = spec.bounded(3 + random.nextInt(6));
            }
            runRandomCalls(random, spec, 400);
        }
    }

    private void runRandomCalls(Random random, ContainerSpec spec, int calls) {
        waiters.clear();
        subscribers.clear();
        Pair pair = new Pair(new ContainerRecord("c1", spec, 8));
        for (int i = 0; i < calls; i++) {
            ContainerCall call = randomCall(random, spec);
            Outcome outcome = pair.run(call);
            if (outcome.status == Outcome.Status.QUEUED) {
                waiters.add(call.id());
            }
            assertEquals(state(pair.owner), state(pair.backup), "after call " + i + " (" + call + ") of " + spec);
            if (i % 97 == 96) {
                pair.backup = roundTrip(pair.owner);
                assertEquals(state(pair.owner), state(pair.backup), "full copy after call " + i);
            }
            if (i == calls / 2) {
                pair = pair.promoted(); // the backup takes over; the old owner becomes its backup
            }
        }
        pair.run(ContainerCall.destroyContainer(next(MEMBER_A)));
        assertEquals(state(pair.owner), state(pair.backup), "after destruction");
    }

    private ContainerCall randomCall(Random random, ContainerSpec spec) {
        UUID member = random.nextBoolean() ? MEMBER_A : MEMBER_B;
        OpId call = next(member);
        int choice = random.nextInt(19);
        long wait = random.nextInt(3) == 0 ? 0 : random.nextBoolean() ? -1 : 60_000;
        String client = random.nextBoolean() ? "client:" + random.nextInt(30) : null; // ids repeat on purpose
        long lease = random.nextInt(4) == 0 ? 1 : 60_000; // some leases run out at once
        return switch (choice) {
            case 0, 1, 2 -> forClient(ContainerCall.write(call, randomItems(random, spec), wait), client, lease);
            case 3 -> forClient(ContainerCall.shift(call, randomItems(random, spec)), client, lease);
            case 4, 5 -> forClient(ContainerCall.retrieve(ContainerCall.Kind.TAKE, call, randomSelectors(random,
                    spec), wait), client, lease);
            case 6 -> ContainerCall.retrieve(ContainerCall.Kind.READ, call, randomSelectors(random, spec), wait);
            case 7 -> forClient(ContainerCall.retrieve(ContainerCall.Kind.DESTROY, call, randomSelectors(random,
                    spec), wait), client, lease);
            case 14 -> ContainerCall.receipts(ContainerCall.Kind.ACK_RECEIPTS, call,
                    List.of("client:" + random.nextInt(30)));
            case 15 -> ContainerCall.receipt(ContainerCall.Kind.RESTORE_RECEIPT, call, "client:" + random.nextInt(30));
            case 16 -> ContainerCall.receipt(ContainerCall.Kind.TAKE_COMPLETED, call, "client:" + random.nextInt(30));
            case 17 -> ContainerCall.receipt(ContainerCall.Kind.FORBID, call, "client:" + random.nextInt(30));
            case 18 -> ContainerCall.sweep(random.nextInt(4) == 0 ? Set.of(MEMBER_B) : Set.of());
            case 8 -> waiters.isEmpty() ? ContainerCall.describe()
                    : ContainerCall.about(ContainerCall.Kind.COLLECT, call, pick(random, waiters));
            case 9 -> waiters.isEmpty() ? ContainerCall.describe()
                    : ContainerCall.about(random.nextBoolean() ? ContainerCall.Kind.WITHDRAW
                    : ContainerCall.Kind.WITHDRAW_AND_UNDO, call, pick(random, waiters));
            case 10 -> {
                subscribers.add(call);
                yield ContainerCall.about(ContainerCall.Kind.SUBSCRIBE, call, call);
            }
            case 11 -> subscribers.isEmpty() ? ContainerCall.readJournal(0, List.of())
                    : ContainerCall.about(ContainerCall.Kind.UNSUBSCRIBE, call, pick(random, subscribers));
            case 12 -> ContainerCall.forgetMembers(random.nextInt(4) == 0 ? Set.of(MEMBER_A) : Set.of(MEMBER_A,
                    MEMBER_B));
            default -> ContainerCall.acknowledge(call, waiters.isEmpty() ? List.of() : List.of(pick(random, waiters)));
        };
    }

    private static ContainerCall forClient(ContainerCall call, String client, long lease) {
        return client == null ? call : call.forClient(client, lease);
    }

    private static OpId pick(Random random, List<OpId> ids) {
        return ids.get(random.nextInt(ids.size()));
    }

    private OpId next(UUID member) {
        return new OpId(member, ++counter);
    }

    private static List<Item> randomItems(Random random, ContainerSpec spec) {
        int count = 1 + random.nextInt(spec.isBounded() ? Math.min(3, spec.capacity()) : 3);
        List<Item> items = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            Entry entry = random.nextBoolean() ? Entry.of(random.nextInt(12))
                    : Tuple.of("t" + random.nextInt(4), random.nextInt(5));
            Item item = Item.of(entry);
            if (spec.keyView() && random.nextBoolean()) {
                item = item.withKey("k" + i + random.nextInt(6));
            }
            if (spec.vectorView() && random.nextBoolean()) {
                item = item.atIndex(i * 10 + random.nextInt(8));
            }
            items.add(item);
        }
        return items;
    }

    private static Selector[] randomSelectors(Random random, ContainerSpec spec) {
        int kind = random.nextInt(6);
        int count = random.nextInt(4) == 0 ? Selector.ALL : 1 + random.nextInt(2);
        Selector first = switch (kind) {
            case 0 -> Selector.order(Order.values()[random.nextInt(4)], count);
            case 1 -> spec.keyView() ? Selector.key("k0" + random.nextInt(6), count == Selector.ALL ? count : 1)
                    : Selector.fifo(count);
            case 2 -> spec.vectorView() ? Selector.vector(random.nextInt(12), count) : Selector.lru(count);
            case 3 -> Selector.template(Template.tuple("t" + random.nextInt(4), EntryType.INTEGER), count);
            case 4 -> Selector.template(Template.type(EntryType.INTEGER), count);
            default -> null;
        };
        if (first == null) {
            return new Selector[0];
        }
        if (random.nextInt(4) == 0) {
            return new Selector[] {first, Selector.order(Order.values()[random.nextInt(4)], 1)};
        }
        return new Selector[] {first};
    }

    @Test
    void aRepeatedCallReturnsItsFirstOutcomeAndChangesNothing() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 8));
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(1)), Item.of(Entry.of(2))), 0));
        ContainerCall take = ContainerCall.retrieve(ContainerCall.Kind.TAKE, next(MEMBER_A), new Selector[0], 0);
        Outcome first = pair.run(take);
        String after = state(pair.owner);
        ContainerCall again = roundTrip(take); // as Hazelcast sends it to the new owner after the old one died
        Outcome second = again.process(new AbstractMap.SimpleEntry<>("c1", pair.owner));
        assertEquals(List.of(Entry.of(1)), first.entries);
        assertEquals(first.entries, second.entries);
        assertEquals(after, state(pair.owner), "not applied twice");
        assertNull(again.getBackupProcessor(), "nothing to back up");
    }

    @Test
    void aClientsTakeIsHeldUntilConfirmedAndACancelFromAnyMemberPutsItBack() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 8));
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(1)), Item.of(Entry.of(2))), 0));
        Outcome taken = pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, next(MEMBER_A), new Selector[0], 0)
                .forClient("k:1", 60_000));
        assertEquals(List.of(Entry.of(1)), taken.entries);
        Outcome again = pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, next(MEMBER_B), new Selector[0], 0)
                .forClient("k:1", 60_000));
        assertEquals(List.of(Entry.of(1)), again.entries, "the same call again gets the same held entries");
        assertEquals(1, pair.owner.contents().size(), "and takes nothing more");
        Outcome forbidden = pair.run(ContainerCall.receipt(ContainerCall.Kind.FORBID, next(MEMBER_B), "k:1"));
        assertTrue(!forbidden.happened, "a take is undone, not reported as done");
        assertEquals(2, pair.owner.contents().size(), "the cancelled take's entry is back");
        Outcome late = pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, next(MEMBER_A), new Selector[0], 0)
                .forClient("k:1", 60_000));
        assertEquals(Outcome.Status.CANCELLED, late.status, "the cancelled call is refused if it comes again");
        assertEquals(state(pair.owner), state(pair.backup));
    }

    @Test
    void aShortLeaseRunsOutOnTimeAmongReceiptsKeptForMinutes() throws Exception {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 8));
        for (int i = 0; i < 50; i++) { // completed writes: their receipts are kept for minutes
            pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(i))), 0).forClient("w:" + i,
                    60_000));
        }
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(99))), 0)); // walks them once
        Outcome taken = pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, next(MEMBER_B), new Selector[0], 0)
                .forClient("k:1", 30));
        assertEquals(List.of(Entry.of(0)), taken.entries);
        assertEquals(50, pair.owner.contents().size());
        Thread.sleep(40);
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(100))), 0));
        assertEquals(52, pair.owner.contents().size(), "the unconfirmed take's entry is back once its lease ran out");
        assertNull(pair.owner.receipts().get("k:1"));
        assertEquals(50, pair.owner.receipts().size(), "the writes' receipts stay");
        assertEquals(state(pair.owner), state(pair.backup));

        pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, next(MEMBER_B), new Selector[0], 0)
                .forClient("k:2", 30));
        pair = pair.promoted(); // a new owner knows nothing of when receipts fall due: it walks them
        Thread.sleep(40);
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(101))), 0));
        assertEquals(53, pair.owner.contents().size(), "a lease held before the promotion runs out too");
        assertEquals(state(pair.owner), state(pair.backup));
    }

    @Test
    void pastTheLimitTheOldestCompletedReceiptsGoAndHeldRemovalsStay() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 8));
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(-1))), 0));
        pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, next(MEMBER_B), new Selector[0], 0)
                .forClient("k:held", 60_000)); // the oldest receipt, and not due for a minute
        int writes = ContainerRules.MAX_RECEIPTS + 5;
        for (int i = 0; i < writes; i++) {
            pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(i))), 0).forClient("w:" + i,
                    60_000));
        }
        Map<String, Receipt> receipts = pair.owner.receipts();
        assertEquals(ContainerRules.MAX_RECEIPTS + 1, receipts.size(), "the limit, and the last call's own receipt");
        assertEquals(Receipt.Kind.HELD, receipts.get("k:held").kind(), "a held removal is never dropped for room");
        for (int i = 0; i < 5; i++) {
            assertNull(receipts.get("w:" + i), "the oldest completed receipts went first");
        }
        assertNotNull(receipts.get("w:5"));
        assertNotNull(receipts.get("w:" + (writes - 1)));
        assertEquals(state(pair.owner), state(pair.backup));
    }

    @Test
    void aServedClientTakeIsHeldForItsOwnLeaseWhoeverServedIt() throws Exception {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 8));
        OpId waiter = next(MEMBER_B);
        pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, waiter, new Selector[0], -1).forClient("k:9", 60_000));
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(1))), 0)); // a call with no lease serves it
        Thread.sleep(5);
        pair.run(ContainerCall.sweep());
        assertEquals(0, pair.owner.contents().size(), "still held: the lease is the take's, not the write's");
        assertEquals(Receipt.Kind.HELD, pair.owner.receipts().get("k:9").kind());
        pair.run(ContainerCall.receipts(ContainerCall.Kind.ACK_RECEIPTS, next(MEMBER_B), List.of("k:9")));
        assertTrue(pair.owner.receipts().isEmpty(), "confirmed: the removal stands");
        assertEquals(state(pair.owner), state(pair.backup));
    }

    @Test
    void aClientsWriteIsReportedOnceToACancel() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO).bounded(1), 8));
        pair.run(ContainerCall.shift(next(MEMBER_A), List.of(Item.of(Entry.of(1)))).forClient("k:2", 60_000));
        Outcome shifted = pair.run(ContainerCall.shift(next(MEMBER_A), List.of(Item.of(Entry.of(2))))
                .forClient("k:3", 60_000));
        assertEquals(List.of(Entry.of(1)), shifted.entries);
        Outcome asked = pair.run(ContainerCall.receipt(ContainerCall.Kind.FORBID, next(MEMBER_B), "k:3"));
        assertTrue(asked.happened, "it happened");
        assertEquals(List.of(Entry.of(1)), asked.entries, "with what it displaced");
        assertEquals(state(pair.owner), state(pair.backup));
    }

    @Test
    void aTakeServedToADepartedMemberIsPutBack() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO).withKeyView(), 8));
        OpId waiter = next(MEMBER_B);
        assertEquals(Outcome.Status.QUEUED, pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, waiter,
                new Selector[] {Selector.key("answer")}, -1)).status);
        Outcome write = pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.keyed("answer", Entry.of(7))), 0));
        assertEquals(List.of(waiter), write.wakes, "the waiter's member is told to collect");
        assertEquals(0, pair.owner.contents().size());
        pair.run(ContainerCall.forgetMembers(Set.of(MEMBER_A))); // B left before collecting
        assertEquals(1, pair.owner.contents().size(), "the answer is back under its key");
        assertEquals(state(pair.owner), state(pair.backup));
        Outcome read = pair.run(ContainerCall.retrieve(ContainerCall.Kind.READ, next(MEMBER_A),
                new Selector[] {Selector.key("answer")}, 0));
        assertEquals(List.of(Entry.of(7)), read.entries);
    }

    @Test
    void aTakeOfADepartedMemberThatArrivesAfterItWasForgottenIsForgottenByTheNextSweep() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 8));
        pair.run(ContainerCall.forgetMembers(Set.of(MEMBER_A))); // B left: the oldest member forgot it
        OpId late = next(MEMBER_B); // sent by B just before it died, run by the owner only now
        assertEquals(Outcome.Status.QUEUED, pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, late,
                new Selector[0], -1)).status);
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(7))), 0));
        assertEquals(0, pair.owner.contents().size(), "served to the late take, which nobody will collect");

        pair.run(ContainerCall.sweep(Set.of(MEMBER_B)));
        assertEquals(1, pair.owner.contents().size(), "the entry is back at once, not after minutes");
        assertEquals(state(pair.owner), state(pair.backup));
        assertEquals(List.of(Entry.of(7)), pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE,
                next(MEMBER_A), new Selector[0], 0)).entries, "and a live member takes it");
    }

    @Test
    void aServedWaiterIsCollectedOnceEvenIfWithdrawnLater() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 8));
        OpId waiter = next(MEMBER_B);
        pair.run(ContainerCall.retrieve(ContainerCall.Kind.TAKE, waiter, new Selector[0], 10_000));
        pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(5))), 0));
        Outcome withdrawn = pair.run(ContainerCall.about(ContainerCall.Kind.WITHDRAW, next(MEMBER_B), waiter));
        assertEquals(Outcome.Status.DONE, withdrawn.status, "served before its time ran out: the result is handed over");
        assertEquals(List.of(Entry.of(5)), withdrawn.entries);
        Outcome collected = pair.run(ContainerCall.about(ContainerCall.Kind.COLLECT, next(MEMBER_B), waiter));
        assertEquals(Outcome.Status.UNKNOWN, collected.status, "and only once");
    }

    @Test
    void subscribersGetAnUnbrokenChainAndTheJournalRepairsIt() {
        Pair pair = new Pair(new ContainerRecord("c1", ContainerSpec.of(Order.FIFO), 4));
        OpId subscription = next(MEMBER_B);
        Outcome subscribed = pair.run(ContainerCall.about(ContainerCall.Kind.SUBSCRIBE, subscription, subscription));
        long previous = subscribed.chainTail;
        for (int i = 0; i < 3; i++) {
            Outcome write = pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(i))), 0));
            assertEquals(Set.of(MEMBER_B), write.eventMembers);
            assertEquals(previous, write.events.get(0).previous(), "each event names its predecessor");
            previous = write.events.get(0).sequence();
        }
        Outcome journal = pair.run(ContainerCall.readJournal(subscribed.chainTail, List.of(subscription)));
        assertTrue(journal.complete);
        assertEquals(3, journal.events.size());
        for (int i = 3; i < 8; i++) {
            pair.run(ContainerCall.write(next(MEMBER_A), List.of(Item.of(Entry.of(i))), 0));
        }
        Outcome tooLate = pair.run(ContainerCall.readJournal(subscribed.chainTail, List.of(subscription)));
        assertTrue(!tooLate.complete, "the journal keeps only the last 4 events: the gap is reported");
        pair.run(ContainerCall.forgetMembers(Set.of(MEMBER_A)));
        Outcome forgotten = pair.run(ContainerCall.readJournal(tooLate.chainTail, List.of(subscription)));
        assertTrue(!forgotten.complete, "a subscription the container forgot is reported as a gap");
    }

    // ---- owner and backup ----

    /** An owner and its backup, each call and change list passing through serialization as between members. */
    private static final class Pair {
        ContainerRecord owner;
        ContainerRecord backup;

        Pair(ContainerRecord record) {
            this.owner = record;
            this.backup = roundTrip(record);
        }

        private Pair(ContainerRecord owner, ContainerRecord backup) {
            this.owner = owner;
            this.backup = backup;
        }

        Outcome run(ContainerCall call) {
            ContainerCall received = roundTrip(call);
            Map.Entry<String, ContainerRecord> entry = new AbstractMap.SimpleEntry<>(owner.id(), owner);
            Outcome outcome = roundTrip(received.process(entry));
            assertSame(owner, entry.getValue());
            EntryProcessor<String, ContainerRecord, Outcome> backupCall = received.getBackupProcessor();
            if (backupCall != null) {
                ApplyChanges replay = roundTrip((ApplyChanges) backupCall);
                replay.process(new AbstractMap.SimpleEntry<>(backup.id(), backup));
            }
            assertNotNull(outcome.status);
            return outcome;
        }

        Pair promoted() {
            return new Pair(backup, owner);
        }
    }

    private static <T> T roundTrip(T value) {
        return SERIALIZATION.toObject(SERIALIZATION.toData(value));
    }

    /** Everything a container holds, in a form that compares equal when the state is the same. */
    private static String state(ContainerRecord record) {
        StringBuilder state = new StringBuilder();
        state.append("entries ").append(record.contents().snapshot()).append('\n');
        state.append("lifo ").append(record.contents().snapshot(Order.LIFO)).append('\n');
        state.append("lru ").append(record.contents().snapshot(Order.LRU)).append('\n');
        state.append("clock ").append(record.contents().clock()).append('\n');
        state.append("sequence ").append(record.sequence()).append(" chain ").append(record.chainTail()).append('\n');
        state.append("waiters ");
        for (WaiterRecord waiter : record.waiters()) {
            state.append(waiter.id()).append(':').append(waiter.kind()).append(' ');
        }
        state.append('\n').append("completions ");
        for (Map.Entry<OpId, Completion> completion : record.completions().entrySet()) {
            state.append(completion.getKey()).append('=').append(completion.getValue().entries())
                    .append(completion.getValue().removed()).append(' ');
        }
        state.append('\n').append("subscribers ").append(record.subscribers()).append('\n');
        state.append("journal ");
        for (Event event : record.journal()) {
            state.append(event).append(' ');
        }
        TreeMap<String, String> done = new TreeMap<>();
        for (Map.Entry<OpId, ContainerRecord.Done> call : record.done().entrySet()) {
            done.put(call.getKey().toString(), call.getValue().outcome().toString());
        }
        state.append('\n').append("done ").append(done).append('\n');
        state.append("destroyed ").append(record.destroyed()).append('\n');
        state.append("receipts ").append(record.receipts());
        return state.toString();
    }
}
