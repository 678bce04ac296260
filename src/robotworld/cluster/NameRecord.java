package robotworld.cluster;

import java.io.IOException;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

import robotworld.space.ContainerSpec;

/** The naming service's value for one name: the container's id and its spec (to answer lookup-or-create). */
final class NameRecord implements IdentifiedDataSerializable {

    private String id;
    private ContainerSpec spec;

    /** For deserialization. */
    NameRecord() {
    }

    NameRecord(String id, ContainerSpec spec) {
        this.id = id;
        this.spec = spec;
    }

    String id() {
        return id;
    }

    ContainerSpec spec() {
        return spec;
    }

    @Override
    public int getFactoryId() {
        return ClusterSerialization.FACTORY_ID;
    }

    @Override
    public int getClassId() {
        return ClusterSerialization.NAME_RECORD;
    }

    @Override
    public void writeData(ObjectDataOutput out) throws IOException {
        out.writeString(id);
        Codec.writeSpec(out, spec);
    }

    @Override
    public void readData(ObjectDataInput in) throws IOException {
        id = in.readString();
        spec = Codec.readSpec(in);
    }
}
