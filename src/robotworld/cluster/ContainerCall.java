package robotworld.cluster;

import java.io.IOException;
import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.TimeUnit;

import com.hazelcast.map.EntryProcessor;
import com.hazelcast.map.ExtendedMapEntry;
import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.internal.PlacedEntry;

/**
 * One call on one container, run by Hazelcast on the member that owns the container's partition, on that
 * partition's thread: so the calls on a container run one at a time, in order (linearizable), and never block.
 * The call's changes are logged and sent to the backups ({@link #getBackupProcessor()}) before the caller gets its
 * answer (synchronous backups). A call that changed something remembers its outcome under its {@link OpId}: if
 * the owner dies after applying it and Hazelcast sends it again to the new owner, the remembered outcome is
 * returned instead of applying it twice.
 */
final class ContainerCall implements EntryProcessor<String, ContainerRecord, Outcome>, IdentifiedDataSerializable {

    private static final System.Logger LOG = System.getLogger(ContainerCall.class.getName());

    /** Tombstones of destroyed containers are kept this long, so late calls learn the container was destroyed. */
    static final long TOMBSTONE_MINUTES = 10;

    /** What the call does. */
    enum Kind {
        READ, TAKE, DESTROY, WRITE, SHIFT, COLLECT, WITHDRAW, WITHDRAW_AND_UNDO, ACKNOWLEDGE, SUBSCRIBE, UNSUBSCRIBE,
        /** Drops the calling member's subscriptions numbered below {@link #after}. */
        UNSUBSCRIBE_OLDER,
        /** Puts removed entries ({@link #restoring}) back: an undone take or destroy. */
        RESTORE,
        /** The clients confirmed these takes ({@link #clients}): their held removals stand. */
        ACK_RECEIPTS,
        /** Puts the held removal of client call {@link #client} back. */
        RESTORE_RECEIPT,
        /** Whether the write or shift of client call {@link #client} happened; forgets it. */
        TAKE_COMPLETED,
        /** Makes sure client call {@link #client} never takes effect. */
        FORBID,
        /** Which of the client calls {@link #clients} this container knows. */
        FIND_RECEIPTS,
        /** Puts back held removals whose lease ran out (for a container nobody calls). */
        SWEEP,
        DESCRIBE, READ_JOURNAL, DESTROY_CONTAINER, FORGET_MEMBERS
    }

    private Kind kind;
    /** The call's id (null for calls that change nothing or may safely run twice). */
    private OpId call;
    /** The calling member's oldest call still in progress: its outcomes before that are no longer needed. */
    private long lowWater;
    private Selector[] selectors = new Selector[0];
    private List<Item> items = List.of();
    /** 0 try once, -1 wait as long as it takes, n: wait up to n ms. */
    private long waitMillis;
    /** The waiter or subscription the call is about. */
    private OpId target;
    private List<OpId> targets = List.of();
    private long after;
    private Set<UUID> live = Set.of();
    /** For a sweep: members known to have left, whose late operations are forgotten as theirs were on leaving. */
    private Set<UUID> departed = Set.of();
    private List<PlacedEntry> restoring = List.of();
    /** The call id of the server's client this call runs for, or null. */
    private String client;
    private List<String> clients = List.of();
    /** How long a removal for a client is held for its confirmation. */
    private long leaseMillis;

    private transient List<Change> changes;

    /** For deserialization. */
    ContainerCall() {
    }

    private ContainerCall(Kind kind, OpId call) {
        this.kind = kind;
        this.call = call;
    }

    static ContainerCall retrieve(Kind kind, OpId call, Selector[] selectors, long waitMillis) {
        ContainerCall c = new ContainerCall(kind, call);
        c.selectors = selectors;
        c.waitMillis = waitMillis;
        return c;
    }

    static ContainerCall write(OpId call, List<Item> items, long waitMillis) {
        ContainerCall c = new ContainerCall(Kind.WRITE, call);
        c.items = items;
        c.waitMillis = waitMillis;
        return c;
    }

    static ContainerCall shift(OpId call, List<Item> items) {
        ContainerCall c = new ContainerCall(Kind.SHIFT, call);
        c.items = items;
        return c;
    }

    /** COLLECT, WITHDRAW, WITHDRAW_AND_UNDO, SUBSCRIBE or UNSUBSCRIBE of {@code target}. */
    static ContainerCall about(Kind kind, OpId call, OpId target) {
        ContainerCall c = new ContainerCall(kind, call);
        c.target = target;
        return c;
    }

    /** Drops the subscriptions of {@code call}'s member on the container that are numbered below {@code below}. */
    static ContainerCall unsubscribeOlder(OpId call, long below) {
        ContainerCall c = new ContainerCall(Kind.UNSUBSCRIBE_OLDER, call);
        c.after = below;
        return c;
    }

    static ContainerCall acknowledge(OpId call, List<OpId> waiters) {
        ContainerCall c = new ContainerCall(Kind.ACKNOWLEDGE, call);
        c.targets = waiters;
        return c;
    }

    static ContainerCall restore(OpId call, List<PlacedEntry> removed) {
        ContainerCall c = new ContainerCall(Kind.RESTORE, call);
        c.restoring = removed;
        return c;
    }

    static ContainerCall describe() {
        return new ContainerCall(Kind.DESCRIBE, null);
    }

    /** The journal after {@code after}; incomplete also if any of {@code subscriptions} is no longer registered. */
    static ContainerCall readJournal(long after, List<OpId> subscriptions) {
        ContainerCall c = new ContainerCall(Kind.READ_JOURNAL, null);
        c.after = after;
        c.targets = subscriptions;
        return c;
    }

    static ContainerCall destroyContainer(OpId call) {
        return new ContainerCall(Kind.DESTROY_CONTAINER, call);
    }

    static ContainerCall forgetMembers(Set<UUID> live) {
        ContainerCall c = new ContainerCall(Kind.FORGET_MEMBERS, null);
        c.live = live;
        return c;
    }

    ContainerCall lowWater(long value) {
        this.lowWater = value;
        return this;
    }

    /** This call on behalf of a server's client whose call id is {@code id}; removals are held {@code lease} ms. */
    ContainerCall forClient(String id, long lease) {
        this.client = id;
        this.leaseMillis = lease;
        return this;
    }

    /** A call about the receipts of client calls: ACK_RECEIPTS or FIND_RECEIPTS of {@code ids}. */
    static ContainerCall receipts(Kind kind, OpId call, List<String> ids) {
        ContainerCall c = new ContainerCall(kind, call);
        c.clients = ids;
        return c;
    }

    /** A call about the receipt of one client call: RESTORE_RECEIPT, TAKE_COMPLETED or FORBID. */
    static ContainerCall receipt(Kind kind, OpId call, String id) {
        ContainerCall c = new ContainerCall(kind, call);
        c.client = id;
        return c;
    }

    static ContainerCall sweep() {
        return sweep(Set.of());
    }

    /**
     * The owner's periodic call: held removals whose lease ran out come back, and what members that left still hold
     * here is forgotten. The oldest member forgets a departed member's operations when it leaves, but an operation
     * the departed member sent just before it died can reach the owner after that; queued then, it would hold what
     * it is served until it counts as abandoned (minutes).
     */
    static ContainerCall sweep(Set<UUID> departed) {
        ContainerCall c = new ContainerCall(Kind.SWEEP, null);
        c.departed = departed;
        return c;
    }

    Kind kind() {
        return kind;
    }

    OpId id() {
        return call;
    }

    // ---- on the owner ----

    @Override
    public Outcome process(Map.Entry<String, ContainerRecord> entry) {
        ContainerRecord record = entry.getValue();
        if (record == null) {
            return Outcome.of(Outcome.Status.NOT_FOUND);
        }
        if (call != null) {
            Outcome earlier = record.doneOutcome(call);
            if (earlier != null) {
                return earlier; // applied before the previous owner died: do not apply it again
            }
        }
        changes = new ArrayList<>();
        record.logInto(changes);
        Outcome outcome;
        try {
            long now = System.currentTimeMillis();
            ContainerRules rules = new ContainerRules(record, now, new Outcome(), leaseMillis);
            if (call != null) {
                rules.collectGarbage(call.member(), lowWater);
            } else if (kind == Kind.SWEEP) {
                rules.expireReceipts();
                if (!departed.isEmpty()) {
                    rules.forgetMembers(member -> !departed.contains(member), false);
                }
            }
            try {
                outcome = run(record, rules);
            } catch (RuntimeException e) {
                // never throw out of here: what was changed must still reach the backups
                LOG.log(Level.ERROR, "call " + this + " failed on container " + entry.getKey(), e);
                outcome = Outcome.of(Outcome.Status.FAILED);
                outcome.message = e.toString();
            }
            if (call != null && !changes.isEmpty()) {
                record.remember(call, outcome, now);
            }
        } finally {
            record.logInto(null);
        }
        if (!changes.isEmpty()) {
            if (record.destroyed() && entry instanceof ExtendedMapEntry<String, ContainerRecord> extended) {
                extended.setValue(record, TOMBSTONE_MINUTES, TimeUnit.MINUTES);
            } else {
                entry.setValue(record);
            }
        }
        return outcome;
    }

    private Outcome run(ContainerRecord record, ContainerRules rules) {
        if (record.destroyed()) {
            return switch (kind) {
                case COLLECT -> rules.collect(target);
                case WITHDRAW -> rules.withdraw(target, false);
                case WITHDRAW_AND_UNDO -> rules.withdraw(target, true);
                case ACKNOWLEDGE -> rules.acknowledge(targets);
                case READ_JOURNAL -> rules.readJournal(after, targets);
                case FORGET_MEMBERS -> rules.forgetMembers(live::contains, true);
                case UNSUBSCRIBE, UNSUBSCRIBE_OLDER, ACK_RECEIPTS, RESTORE_RECEIPT, SWEEP ->
                        Outcome.of(Outcome.Status.DONE);
                case TAKE_COMPLETED -> rules.takeCompleted(client);
                case FORBID -> Outcome.of(Outcome.Status.DONE); // the container went, and the call with it
                case FIND_RECEIPTS -> rules.findReceipts(clients);
                default -> Outcome.of(Outcome.Status.DESTROYED);
            };
        }
        return switch (kind) {
            case READ -> rules.retrieve(call, WaiterRecord.Kind.READ, selectors, waitMillis, client);
            case TAKE -> rules.retrieve(call, WaiterRecord.Kind.TAKE, selectors, waitMillis, client);
            case DESTROY -> rules.retrieve(call, WaiterRecord.Kind.DESTROY, selectors, waitMillis, client);
            case WRITE -> rules.write(call, items, waitMillis, client);
            case SHIFT -> rules.shift(items, client);
            case COLLECT -> rules.collect(target);
            case WITHDRAW -> rules.withdraw(target, false);
            case WITHDRAW_AND_UNDO -> rules.withdraw(target, true);
            case ACKNOWLEDGE -> rules.acknowledge(targets);
            case SUBSCRIBE -> rules.subscribe(target);
            case UNSUBSCRIBE -> rules.unsubscribe(target);
            case UNSUBSCRIBE_OLDER -> rules.unsubscribeOlder(call.member(), after);
            case RESTORE -> rules.restore(call, restoring);
            case ACK_RECEIPTS -> rules.acknowledgeReceipts(clients);
            case RESTORE_RECEIPT -> rules.restoreReceipt(client);
            case TAKE_COMPLETED -> rules.takeCompleted(client);
            case FORBID -> rules.forbid(client);
            case FIND_RECEIPTS -> rules.findReceipts(clients);
            case SWEEP -> rules.done(); // with the wake-ups of what its sweep served (process)
            case DESCRIBE -> rules.describe();
            case READ_JOURNAL -> rules.readJournal(after, targets);
            case DESTROY_CONTAINER -> rules.destroy();
            case FORGET_MEMBERS -> rules.forgetMembers(live::contains, true);
        };
    }

    /** The backups replay exactly the changes this call made; nothing if it made none. */
    @Override
    public EntryProcessor<String, ContainerRecord, Outcome> getBackupProcessor() {
        return changes == null || changes.isEmpty() ? null : new ApplyChanges(changes);
    }

    // ---- serialization ----

    @Override
    public int getFactoryId() {
        return ClusterSerialization.FACTORY_ID;
    }

    @Override
    public int getClassId() {
        return ClusterSerialization.CONTAINER_CALL;
    }

    @Override
    public void writeData(ObjectDataOutput out) throws IOException {
        out.writeByte(kind.ordinal());
        out.writeBoolean(call != null);
        if (call != null) {
            call.write(out);
        }
        out.writeLong(lowWater);
        Codec.writeSelectors(out, selectors);
        Codec.writeItems(out, items);
        out.writeLong(waitMillis);
        out.writeBoolean(target != null);
        if (target != null) {
            target.write(out);
        }
        out.writeInt(targets.size());
        for (OpId waiter : targets) {
            waiter.write(out);
        }
        out.writeLong(after);
        Codec.writeUuids(out, live);
        Codec.writeUuids(out, departed);
        Codec.writePlacedList(out, restoring);
        out.writeString(client);
        out.writeInt(clients.size());
        for (String id : clients) {
            out.writeString(id);
        }
        out.writeLong(leaseMillis);
    }

    @Override
    public void readData(ObjectDataInput in) throws IOException {
        kind = Kind.values()[in.readByte()];
        call = in.readBoolean() ? OpId.read(in) : null;
        lowWater = in.readLong();
        selectors = Codec.readSelectors(in);
        items = Codec.readItems(in);
        waitMillis = in.readLong();
        target = in.readBoolean() ? OpId.read(in) : null;
        int targetCount = in.readInt();
        if (targetCount > 0) {
            targets = new ArrayList<>(targetCount);
            for (int i = 0; i < targetCount; i++) {
                targets.add(OpId.read(in));
            }
        }
        after = in.readLong();
        live = Codec.readUuids(in);
        departed = Codec.readUuids(in);
        restoring = Codec.readPlacedList(in);
        client = in.readString();
        int clientCount = in.readInt();
        if (clientCount > 0) {
            clients = new ArrayList<>(clientCount);
            for (int i = 0; i < clientCount; i++) {
                clients.add(in.readString());
            }
        }
        leaseMillis = in.readLong();
    }

    @Override
    public String toString() {
        return "ContainerCall[" + kind + " " + call + "]";
    }
}
