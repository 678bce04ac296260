package robotworld.space.internal;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;

/**
 * All nodes of a container in an array, for O(1) random choice; removal swaps the last node into the hole.
 * Also the container's authoritative size.
 */
final class RandomPool {

    private Node[] nodes = new Node[16];
    private int size;

    int size() {
        return size;
    }

    void add(Node node) {
        if (size == nodes.length) {
            nodes = Arrays.copyOf(nodes, size * 2);
        }
        node.slot = size;
        nodes[size++] = node;
    }

    void remove(Node node) {
        Node moved = nodes[--size];
        nodes[node.slot] = moved;
        moved.slot = node.slot;
        nodes[size] = null;
    }

    /** Any node, uniformly at random; null when empty. */
    Node any() {
        return size == 0 ? null : nodes[ThreadLocalRandom.current().nextInt(size)];
    }

    /** {@code count} distinct nodes in random order ({@code count <= size}). */
    List<Node> distinct(int count) {
        ThreadLocalRandom random = ThreadLocalRandom.current();
        List<Node> chosen = new ArrayList<>(count);
        if (count * 2 <= size) {
            // sparse: rejection sampling touches only about `count` slots
            Set<Integer> seen = new HashSet<>();
            while (chosen.size() < count) {
                int slot = random.nextInt(size);
                if (seen.add(slot)) {
                    chosen.add(nodes[slot]);
                }
            }
            return chosen;
        }
        Node[] copy = Arrays.copyOf(nodes, size);
        for (int i = 0; i < count; i++) {
            int pick = i + random.nextInt(size - i);
            Node swap = copy[i];
            copy[i] = copy[pick];
            copy[pick] = swap;
            chosen.add(copy[i]);
        }
        return chosen;
    }

    /** Visits every node once, starting at a random slot, until the visitor says stop. */
    void visitFromRandomStart(NodeVisitor visitor) {
        if (size == 0) {
            return;
        }
        int start = ThreadLocalRandom.current().nextInt(size);
        int total = size;
        for (int i = 0; i < total; i++) {
            if (!visitor.visit(nodes[(start + i) % total])) {
                return;
            }
        }
    }

    void clear() {
        Arrays.fill(nodes, 0, size, null);
        size = 0;
    }
}
