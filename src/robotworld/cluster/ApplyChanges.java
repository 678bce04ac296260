package robotworld.cluster;

import java.io.IOException;
import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import com.hazelcast.map.EntryProcessor;
import com.hazelcast.map.ExtendedMapEntry;
import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

/** Runs on a backup: replays the changes the owner's {@link ContainerCall} made, in the same order. */
final class ApplyChanges implements EntryProcessor<String, ContainerRecord, Outcome>, IdentifiedDataSerializable {

    private static final System.Logger LOG = System.getLogger(ApplyChanges.class.getName());

    private List<Change> changes;

    /** For deserialization. */
    ApplyChanges() {
    }

    ApplyChanges(List<Change> changes) {
        this.changes = changes;
    }

    @Override
    public Outcome process(Map.Entry<String, ContainerRecord> entry) {
        ContainerRecord record = entry.getValue();
        if (record == null) {
            // the backup never had this container: it will get the whole record with the next replica sync
            LOG.log(Level.WARNING, "backup of container " + entry.getKey() + " is missing; " + changes.size()
                    + " change(s) not applied");
            return null;
        }
        for (Change change : changes) {
            change.apply(record);
        }
        if (record.destroyed() && entry instanceof ExtendedMapEntry<String, ContainerRecord> extended) {
            extended.setValue(record, ContainerCall.TOMBSTONE_MINUTES, TimeUnit.MINUTES);
        } else {
            entry.setValue(record);
        }
        return null;
    }

    @Override
    public EntryProcessor<String, ContainerRecord, Outcome> getBackupProcessor() {
        return null;
    }

    @Override
    public int getFactoryId() {
        return ClusterSerialization.FACTORY_ID;
    }

    @Override
    public int getClassId() {
        return ClusterSerialization.APPLY_CHANGES;
    }

    @Override
    public void writeData(ObjectDataOutput out) throws IOException {
        out.writeInt(changes.size());
        for (Change change : changes) {
            Change.writeTagged(out, change);
        }
    }

    @Override
    public void readData(ObjectDataInput in) throws IOException {
        int size = in.readInt();
        changes = new ArrayList<>(size);
        for (int i = 0; i < size; i++) {
            changes.add(Change.read(in));
        }
    }
}
