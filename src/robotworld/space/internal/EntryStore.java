package robotworld.space.internal;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.Uniqueness;

/**
 * The entries of one container and every index over them: insertion order, usage order, a random-access pool,
 * and, when the spec asks for them, the KEY view, the VECTOR view and a value index for SET uniqueness. Not
 * thread-safe: the owning {@link ContainerEngine} holds its lock around every call.
 */
final class EntryStore {

    private final ContainerSpec spec;
    private final NodeList byInsertion = NodeList.byInsertion();
    private final NodeList byUsage = NodeList.byUsage();
    private final RandomPool pool = new RandomPool();
    private final Map<String, Node> keys;
    private final VectorSlots vector;
    private final Map<Entry, Node> values;
    private long clock;
    /** Set only for a replicated container ({@link ContainerContents}); null on the embedded path. */
    private Replication replication;

    EntryStore(ContainerSpec spec) {
        this.spec = spec;
        this.keys = spec.keyView() ? new HashMap<>() : null;
        this.vector = spec.vectorView() ? new VectorSlots() : null;
        this.values = spec.uniqueness() == Uniqueness.SET ? new HashMap<>() : null;
    }

    int size() {
        return pool.size();
    }

    /**
     * Reports every change from now on to {@code observer} and indexes nodes by their insertion stamp, so that the
     * same changes can be replayed on a replica ({@link #placeReplica}, {@link #removeReplica},
     * {@link #touchReplica}).
     */
    void replicate(ChangeObserver observer) {
        Map<Long, Node> byStamp = new HashMap<>();
        visitForward(byInsertion, node -> {
            byStamp.put(node.written, node);
            return true;
        });
        replication = new Replication(observer, byStamp);
    }

    long clock() {
        return clock;
    }

    /** Continues stamping after {@code stamp} (a rebuilt replica's clock). */
    void advanceClock(long stamp) {
        clock = Math.max(clock, stamp);
    }

    /** Free places left; {@code Integer.MAX_VALUE} when unbounded. */
    int room() {
        return spec.isBounded() ? spec.capacity() - pool.size() : Integer.MAX_VALUE;
    }

    // ---- lookups ----

    Node byKey(String key) {
        return keys.get(key);
    }

    Node atPosition(int position) {
        return vector.at(position);
    }

    /** Where an appended entry goes: one past the highest occupied position. */
    int vectorEnd() {
        return vector.end();
    }

    /** The stored entry equal to {@code entry} (SET containers only), or null. */
    Node equalTo(Entry entry) {
        return values.get(entry);
    }

    boolean isSet() {
        return values != null;
    }

    /** The node {@code order} would choose next, or null when empty. */
    Node first(Order order) {
        return switch (order) {
            case FIFO -> byInsertion.first();
            case LIFO -> byInsertion.last();
            case LRU -> byUsage.first();
            case RANDOM -> pool.any();
        };
    }

    /** The first {@code count} nodes in {@code order} ({@code count <= size}); all of them for a negative count. */
    List<Node> first(Order order, int count) {
        int wanted = count < 0 ? pool.size() : count;
        if (order == Order.RANDOM) {
            return pool.distinct(wanted);
        }
        List<Node> chosen = new ArrayList<>(wanted);
        visitInOrder(order, node -> {
            chosen.add(node);
            return chosen.size() < wanted;
        });
        return chosen;
    }

    /** Visits nodes in {@code order} until the visitor says stop. */
    void visitInOrder(Order order, NodeVisitor visitor) {
        switch (order) {
            case FIFO -> visitForward(byInsertion, visitor);
            case LIFO -> {
                for (Node node = byInsertion.last(); node != null; node = byInsertion.previous(node)) {
                    if (!visitor.visit(node)) {
                        return;
                    }
                }
            }
            case LRU -> visitForward(byUsage, visitor);
            case RANDOM -> pool.visitFromRandomStart(visitor);
        }
    }

    private static void visitForward(NodeList list, NodeVisitor visitor) {
        for (Node node = list.first(); node != null; node = list.next(node)) {
            if (!visitor.visit(node)) {
                return;
            }
        }
    }

    // ---- changes ----

    /** Stores an entry; the caller has checked that it fits. {@code position} is -1 without a VECTOR view. */
    Node insert(Entry entry, String key, int position) {
        Node node = new Node(entry, key, position, ++clock);
        byInsertion.append(node);
        byUsage.append(node);
        pool.add(node);
        if (key != null) {
            keys.put(key, node);
        }
        if (position >= 0) {
            vector.put(position, node);
        }
        if (values != null) {
            values.put(entry, node);
        }
        if (replication != null) {
            replication.placed(node);
        }
        return node;
    }

    /** Whether removed nodes could all go back now: room, and their keys, positions and (SET) values free. */
    boolean canRestore(List<Node> nodes) {
        if (nodes.size() > room()) {
            return false;
        }
        for (Node node : nodes) {
            if (node.key != null && keys.containsKey(node.key)) {
                return false;
            }
            if (node.position >= 0 && vector.at(node.position) != null) {
                return false;
            }
            if (values != null && values.containsKey(node.entry)) {
                return false;
            }
        }
        return true;
    }

    /** Puts a removed node back into its old place in every structure; the caller checked {@link #canRestore}. */
    void restore(Node node) {
        byInsertion.insertByStamp(node);
        byUsage.insertByStamp(node);
        pool.add(node);
        if (node.key != null) {
            keys.put(node.key, node);
        }
        if (node.position >= 0) {
            vector.put(node.position, node);
        }
        if (values != null) {
            values.put(node.entry, node);
        }
        if (replication != null) {
            replication.placed(node);
        }
    }

    void remove(Node node) {
        byInsertion.unlink(node);
        byUsage.unlink(node);
        pool.remove(node);
        if (node.key != null) {
            keys.remove(node.key);
        }
        if (node.position >= 0) {
            vector.clear(node.position);
        }
        if (values != null) {
            values.remove(node.entry);
        }
        if (replication != null) {
            replication.removed(node);
        }
    }

    /** Marks a node as just used (LRU). */
    void touch(Node node) {
        node.used = ++clock;
        byUsage.moveToEnd(node);
        if (replication != null) {
            replication.observer.touched(node);
        }
    }

    // ---- replicas: replaying the changes a primary reported ----

    /** Puts a node with the primary's stamps into its place in every structure. */
    void placeReplica(Entry entry, String key, int position, long written, long used) {
        Node node = new Node(entry, key, position, written);
        node.used = used;
        clock = Math.max(clock, Math.max(written, used));
        restore(node); // by stamp: an appended node goes last, a restored one back where it was
    }

    void removeReplica(long written) {
        Node node = replication.byStamp.get(written);
        if (node != null) {
            remove(node);
        }
    }

    void touchReplica(long written, long used) {
        Node node = replication.byStamp.get(written);
        if (node != null) {
            node.used = used;
            clock = Math.max(clock, used);
            byUsage.moveToEnd(node);
            replication.observer.touched(node);
        }
    }

    /** Visits every node in insertion order (oldest first). */
    void visitByInsertion(NodeVisitor visitor) {
        visitForward(byInsertion, visitor);
    }

    /** Receives every change of a replicated store. */
    interface ChangeObserver {
        void placed(Node node);

        void removed(Node node);

        void touched(Node node);
    }

    private record Replication(ChangeObserver observer, Map<Long, Node> byStamp) {
        void placed(Node node) {
            byStamp.put(node.written, node);
            observer.placed(node);
        }

        void removed(Node node) {
            byStamp.remove(node.written);
            observer.removed(node);
        }
    }

    void clear() {
        if (replication != null) {
            replication.byStamp.clear();
        }
        byInsertion.clear();
        byUsage.clear();
        pool.clear();
        if (keys != null) {
            keys.clear();
        }
        if (vector != null) {
            vector.clear();
        }
        if (values != null) {
            values.clear();
        }
    }
}
