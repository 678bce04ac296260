package robotworld.cluster;

import com.hazelcast.nio.serialization.DataSerializableFactory;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

/**
 * Creates this package's values when Hazelcast reads them from the network: each is an
 * {@link IdentifiedDataSerializable} with a fixed class id, written field by field ({@link Codec}); no Java
 * serialization, no reflection.
 */
final class ClusterSerialization implements DataSerializableFactory {

    static final int FACTORY_ID = 0x5257; // "RW"

    static final int OUTCOME = 1;
    static final int CONTAINER_RECORD = 2;
    static final int CONTAINER_CALL = 3;
    static final int APPLY_CHANGES = 4;
    static final int NAME_RECORD = 5;
    static final int MEMBER_MESSAGE = 6;
    static final int NAME_CALL = 7;

    @Override
    public IdentifiedDataSerializable create(int typeId) {
        return switch (typeId) {
            case OUTCOME -> new Outcome();
            case CONTAINER_RECORD -> new ContainerRecord();
            case CONTAINER_CALL -> new ContainerCall();
            case APPLY_CHANGES -> new ApplyChanges();
            case NAME_RECORD -> new NameRecord();
            case MEMBER_MESSAGE -> new MemberMessage();
            case NAME_CALL -> new NameCall();
            default -> null;
        };
    }
}
