package robotworld.cluster;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

import robotworld.space.ContainerSpec;
import robotworld.space.internal.ContainerContents;
import robotworld.space.internal.PlacedEntry;

/**
 * Everything one container is in the cluster, held as one map value on the member that owns its partition (and on
 * its backups): the entries, the queue of blocked operations, what was served but not yet collected, the
 * subscriptions, the journal of recent events, and the outcomes of recent calls (so a repeated call is not applied
 * twice). After destruction it stays for a while as a tombstone, so late calls learn that it was destroyed.
 *
 * <p>The methods here are the primitive changes; each is logged as a {@link Change} while a log is set, which is
 * how backups get the same changes. The rules that decide on changes are in {@link ContainerRules}.
 */
final class ContainerRecord implements IdentifiedDataSerializable {

    /** Outcomes kept for repeated calls at most this long (normally dropped as soon as their call has returned). */
    static final long DONE_KEPT_MILLIS = 5 * 60_000;

    private String id;
    private ContainerSpec spec;
    private int journalCapacity;
    private ContainerContents contents;
    private long sequence;
    private long chainTail;
    private final List<WaiterRecord> waiters = new ArrayList<>();
    private final Map<OpId, Completion> completions = new LinkedHashMap<>();
    private final Set<OpId> subscribers = new LinkedHashSet<>();
    private final ArrayDeque<Event> journal = new ArrayDeque<>();
    private final Map<OpId, Done> done = new HashMap<>();
    /** By client call id, oldest first. */
    private final Map<String, Receipt> receipts = new LinkedHashMap<>();
    private boolean destroyed;
    private List<Change> log;
    /**
     * No receipt is due before this time (owner's clock), so the owner need not walk them on every call; unknown
     * ({@code Long.MIN_VALUE}) in a copy that arrived from another member. A cache, neither logged nor serialized.
     */
    private long receiptsDueAt = Long.MIN_VALUE;

    /** For deserialization. */
    ContainerRecord() {
    }

    ContainerRecord(String id, ContainerSpec spec, int journalCapacity) {
        this.id = id;
        this.spec = spec;
        this.journalCapacity = journalCapacity;
        this.contents = new ContainerContents(spec);
    }

    /** A call's outcome and when it was made (owner's clock). */
    record Done(Outcome outcome, long at) {
    }

    // ---- logging ----

    /** Logs every later change into {@code changes}; null stops logging (a backup logs nothing). */
    void logInto(List<Change> changes) {
        log = changes;
        contents.observe(changes == null ? null : change -> changes.add(new Change.Store(change)));
    }

    private void log(Change change) {
        if (log != null) {
            log.add(change);
        }
    }

    // ---- reading ----

    String id() {
        return id;
    }

    ContainerSpec spec() {
        return spec;
    }

    ContainerContents contents() {
        return contents;
    }

    long sequence() {
        return sequence;
    }

    long chainTail() {
        return chainTail;
    }

    List<WaiterRecord> waiters() {
        return waiters;
    }

    WaiterRecord waiter(OpId waiter) {
        for (WaiterRecord record : waiters) {
            if (record.id().equals(waiter)) {
                return record;
            }
        }
        return null;
    }

    Map<OpId, Completion> completions() {
        return completions;
    }

    Set<OpId> subscribers() {
        return subscribers;
    }

    /** The members with at least one subscription. */
    Set<UUID> subscriberMembers() {
        Set<UUID> members = new LinkedHashSet<>();
        for (OpId subscriber : subscribers) {
            members.add(subscriber.member());
        }
        return members;
    }

    ArrayDeque<Event> journal() {
        return journal;
    }

    Outcome doneOutcome(OpId call) {
        Done earlier = done.get(call);
        return earlier == null ? null : earlier.outcome();
    }

    Map<OpId, Done> done() {
        return done;
    }

    Map<String, Receipt> receipts() {
        return receipts;
    }

    boolean destroyed() {
        return destroyed;
    }

    long receiptsDueAt() {
        return receiptsDueAt;
    }

    /** After a walk of the receipts: none of those left is due before {@code at}. */
    void receiptsWalked(long at) {
        receiptsDueAt = at;
    }

    // ---- the primitive changes ----

    void setSequence(long value) {
        sequence = value;
        log(new Change.Sequenced(value));
    }

    void addWaiter(WaiterRecord waiter, boolean first) {
        if (first) {
            waiters.add(0, waiter);
        } else {
            waiters.add(waiter);
        }
        log(new Change.WaiterAdded(waiter, first));
    }

    void removeWaiter(OpId waiter) {
        for (Iterator<WaiterRecord> it = waiters.iterator(); it.hasNext(); ) {
            if (it.next().id().equals(waiter)) {
                it.remove();
                log(new Change.WaiterRemoved(waiter));
                return;
            }
        }
    }

    void putCompletion(OpId waiter, Completion completion) {
        completions.put(waiter, completion);
        log(new Change.Completed(waiter, completion));
    }

    void removeCompletion(OpId waiter) {
        if (completions.remove(waiter) != null) {
            log(new Change.Collected(waiter));
        }
    }

    void addSubscriber(OpId subscription) {
        subscribers.add(subscription);
        log(new Change.Subscribed(subscription));
    }

    void removeSubscriber(OpId subscription) {
        if (subscribers.remove(subscription)) {
            if (subscribers.isEmpty()) {
                journal.clear(); // nobody to repair for; journaling resumes with the next subscription
            }
            log(new Change.Unsubscribed(subscription));
        }
    }

    void journal(Event event) {
        journal.addLast(event);
        chainTail = event.sequence();
        while (journal.size() > journalCapacity) {
            journal.removeFirst();
        }
        log(new Change.Journaled(event));
    }

    void remember(OpId call, Outcome outcome, long at) {
        done.put(call, new Done(outcome, at));
        log(new Change.Remembered(call, outcome, at));
    }

    void forget(OpId call) {
        if (done.remove(call) != null) {
            log(new Change.Forgotten(call));
        }
    }

    void putReceipt(String call, Receipt receipt) {
        receipts.remove(call); // a newer receipt goes last, in time order
        receipts.put(call, receipt);
        if (receiptsDueAt != Long.MIN_VALUE) {
            receiptsDueAt = Math.min(receiptsDueAt, receipt.dueAt());
        }
        log(new Change.ReceiptPut(call, receipt));
    }

    void removeReceipt(String call) {
        if (receipts.remove(call) != null) {
            log(new Change.ReceiptRemoved(call));
        }
    }

    /** Empties the container for good; completions and the journal stay for late collectors and subscribers. */
    void markDestroyed() {
        destroyed = true;
        contents.clear();
        waiters.clear();
        subscribers.clear();
        log(new Change.Destroyed());
    }

    // ---- serialization: the whole record, for migrations and new backups ----

    @Override
    public int getFactoryId() {
        return ClusterSerialization.FACTORY_ID;
    }

    @Override
    public int getClassId() {
        return ClusterSerialization.CONTAINER_RECORD;
    }

    @Override
    public void writeData(ObjectDataOutput out) throws IOException {
        out.writeString(id);
        Codec.writeSpec(out, spec);
        out.writeInt(journalCapacity);
        out.writeLong(contents.clock());
        Codec.writePlacedList(out, contents.snapshot());
        out.writeLong(sequence);
        out.writeLong(chainTail);
        out.writeInt(waiters.size());
        for (WaiterRecord waiter : waiters) {
            waiter.write(out);
        }
        out.writeInt(completions.size());
        for (Map.Entry<OpId, Completion> completion : completions.entrySet()) {
            completion.getKey().write(out);
            completion.getValue().write(out);
        }
        out.writeInt(subscribers.size());
        for (OpId subscriber : subscribers) {
            subscriber.write(out);
        }
        out.writeInt(journal.size());
        for (Event event : journal) {
            event.write(out);
        }
        out.writeInt(done.size());
        for (Map.Entry<OpId, Done> call : done.entrySet()) {
            call.getKey().write(out);
            call.getValue().outcome().writeData(out);
            out.writeLong(call.getValue().at());
        }
        out.writeBoolean(destroyed);
        out.writeInt(receipts.size());
        for (Map.Entry<String, Receipt> receipt : receipts.entrySet()) {
            out.writeString(receipt.getKey());
            receipt.getValue().write(out);
        }
    }

    @Override
    public void readData(ObjectDataInput in) throws IOException {
        id = in.readString();
        spec = Codec.readSpec(in);
        journalCapacity = in.readInt();
        long clock = in.readLong();
        List<PlacedEntry> entries = Codec.readPlacedList(in);
        contents = ContainerContents.load(spec, clock, entries);
        sequence = in.readLong();
        chainTail = in.readLong();
        int waiterCount = in.readInt();
        for (int i = 0; i < waiterCount; i++) {
            waiters.add(WaiterRecord.read(in));
        }
        int completionCount = in.readInt();
        for (int i = 0; i < completionCount; i++) {
            OpId waiter = OpId.read(in);
            completions.put(waiter, Completion.read(in));
        }
        int subscriberCount = in.readInt();
        for (int i = 0; i < subscriberCount; i++) {
            subscribers.add(OpId.read(in));
        }
        int journalSize = in.readInt();
        for (int i = 0; i < journalSize; i++) {
            journal.addLast(Event.read(in));
        }
        int doneCount = in.readInt();
        for (int i = 0; i < doneCount; i++) {
            OpId call = OpId.read(in);
            Outcome outcome = new Outcome();
            outcome.readData(in);
            done.put(call, new Done(outcome, in.readLong()));
        }
        destroyed = in.readBoolean();
        int receiptCount = in.readInt();
        for (int i = 0; i < receiptCount; i++) {
            String call = in.readString();
            receipts.put(call, Receipt.read(in));
        }
    }

    @Override
    public String toString() {
        return "ContainerRecord[" + id + ", " + contents.size() + " entries, " + waiters.size() + " waiting"
                + (destroyed ? ", destroyed" : "") + "]";
    }
}
