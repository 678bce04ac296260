package robotworld.cluster;

import java.io.IOException;
import java.util.Map;

import com.hazelcast.map.EntryProcessor;
import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

/**
 * A change to one name of the naming service, run on the member that owns the name (and, being deterministic,
 * repeated as it is on the backups): claim it for a container unless it is taken, or release it if it still
 * names a given container. Both are safe to repeat, so a call Hazelcast repeats after a member died does no harm.
 */
final class NameCall implements EntryProcessor<String, NameRecord, NameRecord>, IdentifiedDataSerializable {

    private boolean claim;
    private NameRecord record;
    private String id;

    /** For deserialization. */
    NameCall() {
    }

    /** Names {@code wanted}'s container unless the name is taken; answers whichever container it names now. */
    static NameCall claim(NameRecord wanted) {
        NameCall call = new NameCall();
        call.claim = true;
        call.record = wanted;
        return call;
    }

    /** Frees the name if it still names container {@code id}; answers null. */
    static NameCall release(String id) {
        NameCall call = new NameCall();
        call.id = id;
        return call;
    }

    @Override
    public NameRecord process(Map.Entry<String, NameRecord> entry) {
        NameRecord current = entry.getValue();
        if (claim) {
            if (current == null) {
                entry.setValue(record);
                return record;
            }
            return current;
        }
        if (current != null && current.id().equals(id)) {
            entry.setValue(null);
        }
        return null;
    }

    @Override
    public int getFactoryId() {
        return ClusterSerialization.FACTORY_ID;
    }

    @Override
    public int getClassId() {
        return ClusterSerialization.NAME_CALL;
    }

    @Override
    public void writeData(ObjectDataOutput out) throws IOException {
        out.writeBoolean(claim);
        out.writeBoolean(record != null);
        if (record != null) {
            record.writeData(out);
        }
        out.writeString(id);
    }

    @Override
    public void readData(ObjectDataInput in) throws IOException {
        claim = in.readBoolean();
        if (in.readBoolean()) {
            record = new NameRecord();
            record.readData(in);
        }
        id = in.readString();
    }
}
