package robotworld.cluster;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.core.HazelcastInstanceAware;
import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;

/**
 * What a member passes on to another after a call on a container: which of the receiver's waiting operations were
 * served (their threads then collect the result from the container) and the events for the receiver's
 * subscriptions. Sent as a task to the receiving member; it hands itself to that member's {@link ClusterNode}.
 */
final class MemberMessage implements Runnable, IdentifiedDataSerializable, HazelcastInstanceAware {

    private String space;
    private String container;
    private List<OpId> wakes = List.of();
    private List<Event> events = List.of();
    private transient HazelcastInstance instance;

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
    public void setHazelcastInstance(HazelcastInstance hazelcastInstance) {
        this.instance = hazelcastInstance;
    }

    @Override
    public void run() {
        ClusterNode node = ClusterNode.of(instance);
        if (node != null) {
            node.receive(this);
        }
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
