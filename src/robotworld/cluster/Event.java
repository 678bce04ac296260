package robotworld.cluster;

import java.io.IOException;
import java.util.List;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;

import robotworld.space.Entry;
import robotworld.space.Operation;

/**
 * One operation on a container, as journaled for its subscribers. Events form a chain: each names the sequence
 * number of the event before it ({@code previous}), so a member that receives them out of order, or misses one,
 * notices and repairs the chain from the container's journal.
 *
 * @param sequence  the operation's number in the container's history
 * @param previous  the sequence of the journaled event before this one
 * @param operation what happened
 * @param entries   the entries it affected (none for the container's destruction)
 * @param displaced what a shift pushed out
 */
record Event(long sequence, long previous, Operation operation, List<Entry> entries, List<Entry> displaced) {

    void write(ObjectDataOutput out) throws IOException {
        out.writeLong(sequence);
        out.writeLong(previous);
        out.writeByte(operation.ordinal());
        Codec.writeEntries(out, entries);
        Codec.writeEntries(out, displaced);
    }

    static Event read(ObjectDataInput in) throws IOException {
        long sequence = in.readLong();
        long previous = in.readLong();
        Operation operation = Operation.values()[in.readByte()];
        List<Entry> entries = Codec.readEntries(in);
        return new Event(sequence, previous, operation, entries, Codec.readEntries(in));
    }
}
