package robotworld.space.internal;

import java.util.Arrays;

/**
 * The VECTOR view: fixed positions, each empty or holding one node. Positions do not move when others are
 * emptied (a write to an occupied position waits; see the docs), so lookup by position is an array access.
 */
final class VectorSlots {

    private Node[] slots = new Node[16];
    /** One past the highest occupied position: where an appended entry goes. */
    private int end;

    Node at(int position) {
        return position < end ? slots[position] : null;
    }

    int end() {
        return end;
    }

    void put(int position, Node node) {
        if (position >= slots.length) {
            slots = Arrays.copyOf(slots, Math.max(position + 1, slots.length * 2));
        }
        slots[position] = node;
        if (position >= end) {
            end = position + 1;
        }
    }

    void clear(int position) {
        slots[position] = null;
        // keep `end` tight so appends fill from the last occupied position; each trimmed slot was emptied once
        while (end > 0 && slots[end - 1] == null) {
            end--;
        }
    }

    void clear() {
        Arrays.fill(slots, 0, end, null);
        end = 0;
    }
}
