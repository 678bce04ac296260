package robotworld.cluster;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

/**
 * What a member passes on to another after a call on a container: which of the receiver's waiting operations were
 * served (their threads then collect the result from the container) and the events for the receiver's
 * subscriptions. Published on the receiving member's own topic ({@link ClusterNode}), to which only that member
 * listens.
 */
final class MemberMessage implements IdentifiedDataSerializable {

    private String space;
    private String container;
    private List<OpId> wakes = List.of();
    private List<Event> events = List.of();

    /** For deserialization. */
    MemberMessage() {
    }

    MemberMessage(String space, String container, List<OpId> wakes, List<Event> events) {
        this.space = space;
        this.container = container;
        this.wakes = wakes;
        this.events = events;
    }

    String space() {
        return space;
    }

    String container() {
        return container;
    }

    List<OpId> wakes() {
        return wakes;
    }

    List<Event> events() {
        return events;
    }

    @Override
    public int getFactoryId() {
        return ClusterSerialization.FACTORY_ID;
    }

    @Override
    public int getClassId() {
        return ClusterSerialization.MEMBER_MESSAGE;
    }

    @Override
    public void writeData(ObjectDataOutput out) throws IOException {
        out.writeString(space);
        out.writeString(container);
        out.writeInt(wakes.size());
        for (OpId wake : wakes) {
            wake.write(out);
        }
        out.writeInt(events.size());
        for (Event event : events) {
            event.write(out);
        }
    }

    @Override
    public void readData(ObjectDataInput in) throws IOException {
        space = in.readString();
        container = in.readString();
        int wakeCount = in.readInt();
        wakes = new ArrayList<>(wakeCount);
        for (int i = 0; i < wakeCount; i++) {
            wakes.add(OpId.read(in));
        }
        int eventCount = in.readInt();
        events = new ArrayList<>(eventCount);
        for (int i = 0; i < eventCount; i++) {
            events.add(Event.read(in));
        }
    }
}
