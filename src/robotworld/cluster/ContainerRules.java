package robotworld.cluster;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.function.Predicate;

import robotworld.space.Entry;
import robotworld.space.InvalidOperationException;
import robotworld.space.Item;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.internal.ContainerContents;
import robotworld.space.internal.PlacedEntry;

/**
 * The rules of one container, run on the member that owns it, inside one Hazelcast entry processor call: the
 * same as the embedded space's (they share {@link ContainerContents}), with the blocked operations queued in the
 * {@link ContainerRecord} instead of as threads. An operation that cannot happen yet is queued; whenever a call
 * changes the container, the queue is retried oldest first, and each success is stored as a {@link Completion}
 * and reported in the {@link Outcome} as a wake-up for the member whose thread waits for it. Every operation gets
 * the next sequence number; while the container has subscriptions, those that affected entries are journaled and
 * reported as events.
 */
final class ContainerRules {

    /** How long past its own timeout a queued operation may stay before the owner drops it as abandoned. */
    static final long ABANDONED_AFTER_MILLIS = 60_000;
    /** How long a served operation's result waits to be collected before it is undone as abandoned. */
    static final long UNCOLLECTED_AFTER_MILLIS = 120_000;

    /** How many receipts of completed and cancelled calls a container keeps at most. */
    static final int MAX_RECEIPTS = 10_000;

    private final ContainerRecord record;
    private final ContainerContents contents;
    private final long now;
    private final Outcome outcome;
    /** How long a removal for a server's client is held for its confirmation. */
    private final long leaseMillis;

    ContainerRules(ContainerRecord record, long now, Outcome outcome, long leaseMillis) {
        this.record = record;
        this.contents = record.contents();
        this.now = now;
        this.outcome = outcome;
        this.leaseMillis = leaseMillis;
    }

    // ---- operations ----

    /**
     * A read, take or destroy: done now, queued, or not possible. With a client call id ({@code client}), a take or
     * destroy is held under it until confirmed ({@link Receipt}), and a call cancelled before it came is refused.
     */
    Outcome retrieve(OpId call, WaiterRecord.Kind kind, Selector[] selectors, long waitMillis, String client) {
        Outcome settled = settledAlready(client);
        if (settled != null) {
            return settled;
        }
        try {
            ContainerContents.checkSelectors(record.spec(), selectors);
            Completion completion = attempt(kind, selectors, List.of(), List.of());
            if (completion != null) {
                receipt(client, kind, completion, leaseMillis);
                if (kind.mutates()) {
                    serve();
                }
                return done(completion);
            }
        } catch (InvalidOperationException e) {
            return invalid(e);
        }
        return queueOrRefuse(new WaiterRecord(call, kind, selectors, List.of(), List.of(), expiry(waitMillis),
                client, leaseMillis), waitMillis);
    }

    Outcome write(OpId call, List<Item> items, long waitMillis, String client) {
        Outcome settled = settledAlready(client);
        if (settled != null) {
            return settled;
        }
        try {
            ContainerContents.checkWrite(record.spec(), items);
            if (items.isEmpty()) {
                return done(List.of());
            }
            Completion completion = attempt(WaiterRecord.Kind.WRITE, new Selector[0], items, List.of());
            if (completion != null) {
                receipt(client, WaiterRecord.Kind.WRITE, completion, 0);
                serve();
                return done(List.of());
            }
        } catch (InvalidOperationException e) {
            return invalid(e);
        }
        return queueOrRefuse(new WaiterRecord(call, WaiterRecord.Kind.WRITE, new Selector[0], items, List.of(),
                expiry(waitMillis), client, 0), waitMillis);
    }

    Outcome shift(List<Item> items, String client) {
        Outcome settled = settledAlready(client);
        if (settled != null) {
            return settled;
        }
        List<Entry> displaced;
        try {
            ContainerContents.checkItems(record.spec(), items);
            if (items.isEmpty()) {
                return done(List.of());
            }
            displaced = contents.shift(items);
        } catch (InvalidOperationException e) {
            return invalid(e);
        }
        publish(Operation.SHIFT, entriesOf(items), displaced);
        if (client != null) {
            record.putReceipt(client, Receipt.done(displaced, now));
        }
        serve();
        return done(displaced);
    }

    // ---- receipts of a server's clients ----

    /**
     * What a client's call that the container already knows gets: refused if it was cancelled before it came; the
     * same answer again if it happened (a write, a shift, or a take still held): null for a call it does not know.
     */
    private Outcome settledAlready(String client) {
        if (client == null) {
            return null;
        }
        Receipt receipt = record.receipts().get(client);
        if (receipt == null) {
            return null;
        }
        return switch (receipt.kind()) {
            case FORBIDDEN -> {
                record.removeReceipt(client);
                Outcome refused = Outcome.of(Outcome.Status.CANCELLED);
                refused.message = "call " + client + " was cancelled";
                yield refused;
            }
            case DONE -> done(receipt.displaced());
            case HELD -> {
                Outcome again = done(entriesOfPlaced(receipt.held()));
                again.removed = receipt.held();
                yield again;
            }
        };
    }

    /**
     * Keeps what a client's call did under its id: a held removal (for {@code lease} ms, the lease of the call that
     * asked for it), or a write that happened.
     */
    private void receipt(String client, WaiterRecord.Kind kind, Completion completion, long lease) {
        if (client == null || !completion.succeeded()) {
            return;
        }
        if (kind == WaiterRecord.Kind.TAKE || kind == WaiterRecord.Kind.DESTROY) {
            if (!completion.removed().isEmpty()) {
                record.putReceipt(client, Receipt.held(completion.removed(), now, lease));
            }
        } else if (kind == WaiterRecord.Kind.WRITE) {
            record.putReceipt(client, Receipt.done(List.of(), now));
        }
    }

    /** The clients confirmed these takes: their removals stand. */
    Outcome acknowledgeReceipts(List<String> clients) {
        for (String client : clients) {
            Receipt receipt = record.receipts().get(client);
            if (receipt != null && receipt.kind() == Receipt.Kind.HELD) {
                record.removeReceipt(client);
            }
        }
        return Outcome.of(Outcome.Status.DONE);
    }

    /** Puts a held removal back (its call was cancelled); {@code happened} says whether there was one. */
    Outcome restoreReceipt(String client) {
        Receipt receipt = record.receipts().get(client);
        Outcome restored = Outcome.of(Outcome.Status.DONE);
        if (receipt != null && receipt.kind() == Receipt.Kind.HELD) {
            record.removeReceipt(client);
            undoHeld(client, receipt);
            serve();
            restored = outcome;
            restored.status = Outcome.Status.DONE;
            restored.happened = true;
        }
        return restored;
    }

    /** Whether a write or shift of the client happened: with what it displaced; forgets it. */
    Outcome takeCompleted(String client) {
        Receipt receipt = record.receipts().get(client);
        Outcome answer = Outcome.of(Outcome.Status.DONE);
        if (receipt != null && receipt.kind() == Receipt.Kind.DONE) {
            record.removeReceipt(client);
            answer.happened = true;
            answer.entries = receipt.displaced();
        }
        return answer;
    }

    /**
     * Makes sure a client's call never takes effect: one that happened meanwhile is reported ({@code happened},
     * with what a shift displaced); a held removal is put back; a queued one is withdrawn; and the call is refused
     * if it still comes.
     */
    Outcome forbid(String client) {
        Receipt receipt = record.receipts().get(client);
        if (receipt != null && receipt.kind() == Receipt.Kind.DONE) {
            record.removeReceipt(client);
            Outcome happened = Outcome.of(Outcome.Status.DONE);
            happened.happened = true;
            happened.entries = receipt.displaced();
            return happened;
        }
        if (receipt != null && receipt.kind() == Receipt.Kind.HELD) {
            undoHeld(client, receipt);
        }
        for (WaiterRecord waiter : List.copyOf(record.waiters())) {
            if (client.equals(waiter.client())) {
                record.removeWaiter(waiter.id());
            }
        }
        record.putReceipt(client, Receipt.forbidden(now));
        serve();
        outcome.status = Outcome.Status.DONE;
        return outcome;
    }

    /** Which of these client calls the container knows (a receipt, or a queued operation). */
    Outcome findReceipts(List<String> clients) {
        List<String> known = new ArrayList<>();
        for (String client : clients) {
            if (record.receipts().containsKey(client) || isQueued(client)) {
                known.add(client);
            }
        }
        Outcome found = Outcome.of(Outcome.Status.DONE);
        found.calls = known;
        return found;
    }

    private boolean isQueued(String client) {
        for (WaiterRecord waiter : record.waiters()) {
            if (client.equals(waiter.client())) {
                return true;
            }
        }
        return false;
    }

    /**
     * Puts a held removal's entries back (its lease ran out, or its call was cancelled); the caller removed its
     * receipt. If they do not fit now they wait first in the queue, under an id made from the client's call id.
     */
    private void undoHeld(String client, Receipt receipt) {
        OpId id = new OpId(UUID.nameUUIDFromBytes(client.getBytes(java.nio.charset.StandardCharsets.UTF_8)), -1);
        undo(new Completion(entriesOfPlaced(receipt.held()), receipt.held(), null, now), id);
    }

    private Outcome queueOrRefuse(WaiterRecord waiter, long waitMillis) {
        if (waitMillis == 0) {
            return Outcome.of(Outcome.Status.NOT_POSSIBLE);
        }
        record.addWaiter(waiter, false);
        outcome.status = Outcome.Status.QUEUED;
        return outcome;
    }

    private long expiry(long waitMillis) {
        return waitMillis < 0 ? Long.MAX_VALUE : now + waitMillis + ABANDONED_AFTER_MILLIS;
    }

    // ---- the waiting member's side ----

    /** Hands over a served operation's result; or says it still waits, or is unknown. */
    Outcome collect(OpId waiter) {
        Completion completion = record.completions().get(waiter);
        if (completion != null) {
            record.removeCompletion(waiter);
            return completed(completion);
        }
        if (record.waiter(waiter) != null) {
            return Outcome.of(Outcome.Status.QUEUED);
        }
        return Outcome.of(record.destroyed() ? Outcome.Status.DESTROYED : Outcome.Status.UNKNOWN);
    }

    /**
     * Takes a waiter out of the queue (its time ran out, or its thread was interrupted). If it was served
     * meanwhile, its result is handed over, or with {@code undo} put back (a take's entries return).
     */
    Outcome withdraw(OpId waiter, boolean undo) {
        Completion completion = record.completions().get(waiter);
        if (completion != null) {
            record.removeCompletion(waiter);
            if (!undo) {
                return completed(completion);
            }
            undo(completion, waiter);
            serve();
            outcome.status = Outcome.Status.WITHDRAWN;
            return outcome;
        }
        if (record.waiter(waiter) != null) {
            record.removeWaiter(waiter);
            outcome.status = Outcome.Status.WITHDRAWN;
            return outcome;
        }
        return Outcome.of(record.destroyed() ? Outcome.Status.DESTROYED : Outcome.Status.UNKNOWN);
    }

    /** Results that reached their threads through a wake-up message: no longer needed. */
    Outcome acknowledge(List<OpId> waiters) {
        for (OpId waiter : waiters) {
            record.removeCompletion(waiter);
        }
        return Outcome.of(Outcome.Status.DONE);
    }

    private Outcome completed(Completion completion) {
        if (!completion.succeeded()) {
            return Outcome.invalid(completion.failure());
        }
        return done(completion);
    }

    /**
     * Puts removed entries back where they were (an undone take or destroy), announced as a write; if they do not
     * fit now, they wait first in the queue, so they are never lost while the container exists.
     */
    Outcome restore(OpId call, List<PlacedEntry> removed) {
        undo(new Completion(entriesOfPlaced(removed), removed, null, now), call);
        serve();
        outcome.status = Outcome.Status.DONE;
        return outcome;
    }

    // ---- notifications ----

    Outcome subscribe(OpId subscription) {
        record.addSubscriber(subscription);
        outcome.status = Outcome.Status.DONE;
        outcome.sequence = record.sequence();
        outcome.chainTail = record.chainTail();
        return outcome;
    }

    Outcome unsubscribe(OpId subscription) {
        record.removeSubscriber(subscription);
        return Outcome.of(Outcome.Status.DONE);
    }

    /**
     * Drops subscriptions of {@code member} numbered below {@code below}: it no longer knows them (their
     * registration's answer was lost, or they ended and their unregistration failed).
     */
    Outcome unsubscribeOlder(UUID member, long below) {
        for (OpId subscriber : List.copyOf(record.subscribers())) {
            if (subscriber.member().equals(member) && subscriber.counter() < below) {
                record.removeSubscriber(subscriber);
            }
        }
        return Outcome.of(Outcome.Status.DONE);
    }

    /**
     * The journaled events after {@code after}, and whether they continue the chain from there without a gap and
     * {@code subscriptions} are all still registered (a member thought gone may have lost them).
     */
    Outcome readJournal(long after, List<OpId> subscriptions) {
        List<Event> events = new ArrayList<>();
        for (Event event : record.journal()) {
            if (event.sequence() > after) {
                events.add(event);
            }
        }
        Outcome read = Outcome.of(Outcome.Status.DONE);
        read.events = events;
        read.complete = (events.isEmpty() ? record.chainTail() == after : events.get(0).previous() == after)
                && (record.destroyed() || record.subscribers().containsAll(subscriptions));
        read.chainTail = record.chainTail();
        return read;
    }

    // ---- the container as a whole ----

    Outcome describe() {
        Outcome info = Outcome.of(Outcome.Status.DONE);
        info.spec = record.spec();
        info.size = contents.size();
        info.blocked = record.waiters().size();
        info.subscriptions = record.subscribers().size();
        info.sequence = record.sequence();
        info.chainTail = record.chainTail();
        return info;
    }

    /** Destroys the container: its waiters fail, its subscribers get the destruction as their last event. */
    Outcome destroy() {
        for (WaiterRecord waiter : record.waiters()) {
            if (waiter.kind() != WaiterRecord.Kind.RESTORE) {
                outcome.addWake(waiter.id());
            }
        }
        publish(Operation.DESTROY_CONTAINER, List.of(), List.of());
        record.markDestroyed();
        outcome.status = Outcome.Status.DONE;
        outcome.spec = record.spec(); // the caller frees its name
        return outcome;
    }

    /**
     * Forgets members that left the cluster: their queued operations and subscriptions go, and what was served to
     * them but never collected is undone (a take's entries return), since no thread is left to receive it.
     *
     * @param wakeLive whether what was served to live members but not collected yet is woken again (when a member
     *                 has just left: it may have been the one to pass the wake-up on, and died first)
     */
    Outcome forgetMembers(Predicate<UUID> live, boolean wakeLive) {
        boolean changed = false;
        for (WaiterRecord waiter : List.copyOf(record.waiters())) {
            if (waiter.kind() != WaiterRecord.Kind.RESTORE && !live.test(waiter.id().member())) {
                record.removeWaiter(waiter.id());
                changed = true;
            }
        }
        for (Map.Entry<OpId, Completion> completion : List.copyOf(record.completions().entrySet())) {
            if (!live.test(completion.getKey().member())) {
                record.removeCompletion(completion.getKey());
                undo(completion.getValue(), completion.getKey());
                changed = true;
            } else if (wakeLive) {
                outcome.addWake(completion.getKey()); // else the waiter would only find out at its next look
            }
        }
        for (OpId subscriber : List.copyOf(record.subscribers())) {
            if (!live.test(subscriber.member())) {
                record.removeSubscriber(subscriber);
            }
        }
        for (OpId call : List.copyOf(record.done().keySet())) {
            if (!live.test(call.member())) {
                record.forget(call);
            }
        }
        if (changed && !record.destroyed()) {
            serve();
        }
        outcome.status = Outcome.Status.DONE;
        return outcome;
    }

    /** The outcome of a call that only maintained the container: done, with the wake-ups and events it caused. */
    Outcome done() {
        outcome.status = Outcome.Status.DONE;
        return outcome;
    }

    /**
     * Puts back held removals whose lease ran out, and forgets receipts of completed and cancelled calls after a
     * while (and beyond {@link #MAX_RECEIPTS}).
     */
    void expireReceipts() {
        if (record.receipts().isEmpty()) {
            return;
        }
        // a busy container holds thousands of receipts, too many to walk on every call: walk them only when one
        // can be due, and between walks drop the oldest completed ones past the limit from the front (oldest first)
        int surplus = record.receipts().size() - MAX_RECEIPTS;
        List<Map.Entry<String, Receipt>> due = new ArrayList<>();
        if (now >= record.receiptsDueAt()) {
            long nextDue = Long.MAX_VALUE;
            for (Map.Entry<String, Receipt> receipt : record.receipts().entrySet()) {
                Receipt value = receipt.getValue();
                boolean expired = value.isDue(now) || (value.kind() != Receipt.Kind.HELD && surplus-- > 0);
                if (expired) {
                    due.add(receipt);
                } else {
                    nextDue = Math.min(nextDue, value.dueAt());
                }
            }
            record.receiptsWalked(nextDue); // before the removals below, whose serving may hold new removals
        } else if (surplus > 0) {
            for (Iterator<Map.Entry<String, Receipt>> it = record.receipts().entrySet().iterator();
                 surplus > 0 && it.hasNext(); ) {
                Map.Entry<String, Receipt> receipt = it.next();
                if (receipt.getValue().kind() != Receipt.Kind.HELD) {
                    due.add(receipt);
                    surplus--;
                }
            }
        } else {
            return;
        }
        for (Map.Entry<String, Receipt> receipt : due) {
            record.removeReceipt(receipt.getKey());
            if (receipt.getValue().kind() == Receipt.Kind.HELD) {
                undoHeld(receipt.getKey(), receipt.getValue()); // nobody confirmed it: the entries come back
            }
        }
        if (!due.isEmpty() && !record.destroyed()) {
            serve();
        }
    }

    void collectGarbage(UUID caller, long lowWater) {
        expireReceipts();
        if (!record.done().isEmpty()) {
            List<OpId> finished = new ArrayList<>();
            for (Map.Entry<OpId, ContainerRecord.Done> call : record.done().entrySet()) {
                boolean returned = call.getKey().member().equals(caller) && call.getKey().counter() < lowWater;
                if (returned || now - call.getValue().at() > ContainerRecord.DONE_KEPT_MILLIS) {
                    finished.add(call.getKey());
                }
            }
            finished.forEach(record::forget);
        }
        if (!record.completions().isEmpty()) {
            List<Map.Entry<OpId, Completion>> abandoned = new ArrayList<>();
            for (Map.Entry<OpId, Completion> completion : record.completions().entrySet()) {
                if (now - completion.getValue().at() > UNCOLLECTED_AFTER_MILLIS) {
                    abandoned.add(completion);
                }
            }
            for (Map.Entry<OpId, Completion> completion : abandoned) {
                record.removeCompletion(completion.getKey());
                undo(completion.getValue(), completion.getKey());
            }
            if (!abandoned.isEmpty() && !record.destroyed()) {
                serve();
            }
        }
    }

    // ---- mechanics ----

    /**
     * Tries one operation against the current contents; on success applies it, publishes it and returns what it
     * did, else returns null (it must keep waiting).
     */
    private Completion attempt(WaiterRecord.Kind kind, Selector[] selectors, List<Item> items,
                               List<PlacedEntry> restoring) {
        switch (kind) {
            case READ -> {
                List<Entry> entries = contents.read(selectors);
                if (entries == null) {
                    return null;
                }
                publish(Operation.READ, entries, List.of());
                return new Completion(entries, List.of(), null, now);
            }
            case TAKE, DESTROY -> {
                List<PlacedEntry> removed = contents.remove(selectors);
                if (removed == null) {
                    return null;
                }
                List<Entry> entries = entriesOfPlaced(removed);
                publish(kind == WaiterRecord.Kind.TAKE ? Operation.TAKE : Operation.DESTROY, entries, List.of());
                return new Completion(entries, removed, null, now);
            }
            case WRITE -> {
                if (!contents.write(items)) {
                    return null;
                }
                publish(Operation.WRITE, entriesOf(items), List.of());
                return new Completion(List.of(), List.of(), null, now);
            }
            default -> {
                if (!contents.restore(restoring)) {
                    return null;
                }
                publish(Operation.WRITE, entriesOfPlaced(restoring), List.of());
                return new Completion(List.of(), List.of(), null, now);
            }
        }
    }

    /**
     * Retries the queued operations, oldest first, and hands each success to its member. After one that changed
     * the container succeeds, starts again from the oldest, since the change may have unblocked one skipped before.
     */
    private void serve() {
        dropAbandonedWaiters();
        boolean changed = true;
        while (changed && !record.waiters().isEmpty()) {
            changed = false;
            for (int i = 0; i < record.waiters().size(); i++) {
                WaiterRecord waiter = record.waiters().get(i);
                Completion completion;
                try {
                    completion = attempt(waiter.kind(), waiter.selectors(), waiter.items(), waiter.restoring());
                } catch (InvalidOperationException e) {
                    completion = new Completion(List.of(), List.of(), e.getMessage(), now);
                }
                if (completion == null) {
                    continue;
                }
                record.removeWaiter(waiter.id());
                i--;
                if (waiter.kind() != WaiterRecord.Kind.RESTORE) {
                    if (waiter.client() != null) {
                        receipt(waiter.client(), waiter.kind(), completion, waiter.lease());
                        // the receipt holds the entries now: undoing the completion must not put them back twice
                        completion = new Completion(completion.entries(), List.of(), completion.failure(),
                                completion.at());
                    }
                    record.putCompletion(waiter.id(), completion);
                    outcome.addWake(waiter.id());
                }
                if (waiter.kind().mutates() && completion.succeeded()) {
                    changed = true;
                    break;
                }
            }
        }
    }

    private void dropAbandonedWaiters() {
        List<WaiterRecord> waiters = record.waiters();
        for (int i = waiters.size() - 1; i >= 0; i--) {
            if (waiters.get(i).expiresAt() < now) {
                record.removeWaiter(waiters.get(i).id());
            }
        }
    }

    /** Puts a served take's or destroy's entries back; if they do not fit now, they wait first in the queue. */
    private void undo(Completion completion, OpId waiter) {
        if (completion.removed().isEmpty() || record.destroyed()) {
            return;
        }
        if (contents.restore(completion.removed())) {
            publish(Operation.WRITE, entriesOfPlaced(completion.removed()), List.of());
        } else {
            record.addWaiter(new WaiterRecord(waiter, WaiterRecord.Kind.RESTORE, new Selector[0], List.of(),
                    completion.removed(), Long.MAX_VALUE, null, 0), true);
        }
    }

    /** Every completed operation gets the next sequence number; subscribers hear of those that touched entries. */
    private void publish(Operation operation, List<Entry> entries, List<Entry> displaced) {
        long sequence = record.sequence() + 1;
        record.setSequence(sequence);
        boolean reported = !entries.isEmpty() || operation == Operation.DESTROY_CONTAINER;
        if (reported && !record.subscribers().isEmpty()) {
            Event event = new Event(sequence, record.chainTail(), operation, entries, displaced);
            record.journal(event);
            outcome.addEvent(event, record.subscriberMembers());
        }
    }

    private Outcome done(List<Entry> entries) {
        outcome.status = Outcome.Status.DONE;
        outcome.entries = entries;
        return outcome;
    }

    private Outcome done(Completion completion) {
        done(completion.entries());
        outcome.removed = completion.removed();
        return outcome;
    }

    private static Outcome invalid(InvalidOperationException e) {
        return Outcome.invalid(e.getMessage());
    }

    private static List<Entry> entriesOf(List<Item> items) {
        List<Entry> entries = new ArrayList<>(items.size());
        for (Item item : items) {
            entries.add(item.entry());
        }
        return List.copyOf(entries);
    }

    private static List<Entry> entriesOfPlaced(List<PlacedEntry> placed) {
        List<Entry> entries = new ArrayList<>(placed.size());
        for (PlacedEntry entry : placed) {
            entries.add(entry.entry());
        }
        return List.copyOf(entries);
    }
}
