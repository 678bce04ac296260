package robotworld.cluster;

import java.io.IOException;
import java.util.List;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;

import robotworld.space.Entry;
import robotworld.space.internal.PlacedEntry;

/**
 * What happened to a waiting operation when the container served it: its entries (for a take or destroy also
 * where they stood, so the removal can be undone if nobody collects it), or why it failed.
 *
 * @param entries the entries read, taken or destroyed; empty for a write
 * @param removed for a take or destroy, the removed entries with their places; empty otherwise
 * @param failure null on success; otherwise why it can never succeed (an invalid operation)
 * @param at      when it was served, in the owning member's clock
 */
record Completion(List<Entry> entries, List<PlacedEntry> removed, String failure, long at) {

    boolean succeeded() {
        return failure == null;
    }

    void write(ObjectDataOutput out) throws IOException {
        Codec.writeEntries(out, entries);
        Codec.writePlacedList(out, removed);
        out.writeString(failure);
        out.writeLong(at);
    }

    static Completion read(ObjectDataInput in) throws IOException {
        List<Entry> entries = Codec.readEntries(in);
        List<PlacedEntry> removed = Codec.readPlacedList(in);
        String failure = in.readString();
        return new Completion(entries, removed, failure, in.readLong());
    }
}
