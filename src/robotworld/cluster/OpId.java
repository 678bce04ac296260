package robotworld.cluster;

import java.io.IOException;
import java.util.UUID;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;

/**
 * Names one call a member made on the cluster (and a waiter or subscription it created): the member's id plus a
 * number that member never uses twice. The container remembers the outcome under this id, so a call that
 * Hazelcast repeats after the owning member died is not applied twice.
 *
 * @param member  the member that made the call
 * @param counter its number for the call, increasing
 */
record OpId(UUID member, long counter) {

    void write(ObjectDataOutput out) throws IOException {
        Codec.writeUuid(out, member);
        out.writeLong(counter);
    }

    static OpId read(ObjectDataInput in) throws IOException {
        UUID member = Codec.readUuid(in);
        return new OpId(member, in.readLong());
    }

    @Override
    public String toString() {
        return member.toString().substring(0, 8) + "/" + counter;
    }
}
