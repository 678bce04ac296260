package robotworld.cluster;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.UUID;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.internal.PlacedEntry;

/**
 * What a call on a container did, as the owning member answers it: a status and the result, plus the effects the
 * calling member must pass on: waiting operations the call served (to wake on their members) and events for the
 * members that have subscriptions on the container.
 */
final class Outcome implements IdentifiedDataSerializable {

    /** How the call ended. */
    enum Status {
        /** It happened; the result is in {@link #entries}. */
        DONE,
        /** It must wait: a waiter is queued under the call's id. */
        QUEUED,
        /** It could not happen at once and was not allowed to wait. */
        NOT_POSSIBLE,
        /** There is no such container. */
        NOT_FOUND,
        /** The container was destroyed. */
        DESTROYED,
        /** It can never succeed; {@link #message} says why. */
        INVALID,
        /** A waiter was taken out of the queue before it was served. */
        WITHDRAWN,
        /** The container knows no such waiter. */
        UNKNOWN,
        /** The call failed on the owner for a reason of its own ({@link #message}); what it changed is kept. */
        FAILED,
        /** Its client cancelled it before it arrived: refused, no effect. */
        CANCELLED
    }

    Status status;
    List<Entry> entries = List.of();
    /** For a take or destroy: the removed entries with their places, so that the removal can be undone. */
    List<PlacedEntry> removed = List.of();
    String message;
    /** Waiting operations the call served (or failed): their members wake their threads to collect the result. */
    List<OpId> wakes = List.of();
    List<Event> events = List.of();
    Set<UUID> eventMembers = Set.of();
    /** Subscribe: the container's latest sequence and the sequence its event chain continues from. */
    long sequence;
    long chainTail;
    /** Describe. */
    ContainerSpec spec;
    int size;
    int blocked;
    int subscriptions;
    /** Journal reads: whether the events continue the chain from the asked point without a gap. */
    boolean complete;
    /** Receipt searches: the client call ids of those asked about that this container knows. */
    List<String> calls = List.of();
    /** A receipt query: whether the call it asked about had taken effect (a write or shift), with what it displaced. */
    boolean happened;

    Outcome() {
    }

    Outcome(Status status) {
        this.status = status;
    }

    static Outcome of(Status status) {
        return new Outcome(status);
    }

    static Outcome done(List<Entry> entries) {
        Outcome outcome = new Outcome(Status.DONE);
        outcome.entries = entries;
        return outcome;
    }

    static Outcome invalid(String message) {
        Outcome outcome = new Outcome(Status.INVALID);
        outcome.message = message;
        return outcome;
    }

    void addWake(OpId wake) {
        if (wakes.isEmpty()) {
            wakes = new ArrayList<>();
        }
        wakes.add(wake);
    }

    void addEvent(Event event, Set<UUID> members) {
        if (events.isEmpty()) {
            events = new ArrayList<>();
            eventMembers = new HashSet<>();
        }
        events.add(event);
        eventMembers.addAll(members);
    }

    /** Whether there is anything to pass on to other members. */
    boolean hasEffects() {
        return !wakes.isEmpty() || !events.isEmpty();
    }

    @Override
    public int getFactoryId() {
        return ClusterSerialization.FACTORY_ID;
    }

    @Override
    public int getClassId() {
        return ClusterSerialization.OUTCOME;
    }

    @Override
    public void writeData(ObjectDataOutput out) throws IOException {
        out.writeByte(status.ordinal());
        Codec.writeEntries(out, entries);
        Codec.writePlacedList(out, removed);
        out.writeString(message);
        out.writeInt(wakes.size());
        for (OpId wake : wakes) {
            wake.write(out);
        }
        out.writeInt(events.size());
        for (Event event : events) {
            event.write(out);
        }
        out.writeInt(eventMembers.size());
        for (UUID member : eventMembers) {
            Codec.writeUuid(out, member);
        }
        out.writeLong(sequence);
        out.writeLong(chainTail);
        out.writeBoolean(spec != null);
        if (spec != null) {
            Codec.writeSpec(out, spec);
        }
        out.writeInt(size);
        out.writeInt(blocked);
        out.writeInt(subscriptions);
        out.writeBoolean(complete);
        out.writeInt(calls.size());
        for (String call : calls) {
            out.writeString(call);
        }
        out.writeBoolean(happened);
    }

    @Override
    public void readData(ObjectDataInput in) throws IOException {
        status = Status.values()[in.readByte()];
        entries = Codec.readEntries(in);
        removed = Codec.readPlacedList(in);
        message = in.readString();
        int wakeCount = in.readInt();
        if (wakeCount > 0) {
            wakes = new ArrayList<>(wakeCount);
            for (int i = 0; i < wakeCount; i++) {
                wakes.add(OpId.read(in));
            }
        }
        int eventCount = in.readInt();
        if (eventCount > 0) {
            events = new ArrayList<>(eventCount);
            for (int i = 0; i < eventCount; i++) {
                events.add(Event.read(in));
            }
        }
        int memberCount = in.readInt();
        if (memberCount > 0) {
            eventMembers = new HashSet<>();
            for (int i = 0; i < memberCount; i++) {
                eventMembers.add(Codec.readUuid(in));
            }
        }
        sequence = in.readLong();
        chainTail = in.readLong();
        if (in.readBoolean()) {
            spec = Codec.readSpec(in);
        }
        size = in.readInt();
        blocked = in.readInt();
        subscriptions = in.readInt();
        complete = in.readBoolean();
        int callCount = in.readInt();
        if (callCount > 0) {
            calls = new ArrayList<>(callCount);
            for (int i = 0; i < callCount; i++) {
                calls.add(in.readString());
            }
        }
        happened = in.readBoolean();
    }

    @Override
    public String toString() {
        return "Outcome[" + status + (entries.isEmpty() ? "" : " " + entries) + (message == null ? "" : " " + message)
                + "]";
    }
}
