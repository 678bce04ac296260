package robotworld.space.internal;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedList;
import java.util.List;
import java.util.Map;

/**
 * The blocked operations of one container, oldest first, with the waits for one key kept apart: a take of key k
 * (the answer a caller waits for) can only succeed once an entry under k arrives, so a change that brings other
 * keys does not retry it. Without this, every answer shifted into a container with a thousand waiting callers
 * would retry all thousand. Guarded by the container's lock.
 */
final class WaiterQueue {

    private final LinkedList<Waiter> general = new LinkedList<>();
    private final Map<String, ArrayDeque<Waiter>> byKey = new HashMap<>();
    private long nextSeq;
    private long firstSeq;
    private int size;

    boolean isEmpty() {
        return size == 0;
    }

    int size() {
        return size;
    }

    /** Queues a waiter behind all others. */
    void addLast(Waiter waiter) {
        waiter.seq = ++nextSeq;
        if (waiter.key != null) {
            byKey.computeIfAbsent(waiter.key, k -> new ArrayDeque<>(2)).addLast(waiter);
        } else {
            general.addLast(waiter);
        }
        size++;
    }

    /** Queues a waiter before all others. */
    void addFirst(Waiter waiter) {
        waiter.seq = --firstSeq;
        general.addFirst(waiter);
        size++;
    }

    void remove(Waiter waiter) {
        boolean removed;
        if (waiter.key != null) {
            ArrayDeque<Waiter> queue = byKey.get(waiter.key);
            removed = queue != null && queue.remove(waiter);
            if (queue != null && queue.isEmpty()) {
                byKey.remove(waiter.key);
            }
        } else {
            removed = general.remove(waiter);
        }
        if (removed) {
            size--;
        }
    }

    /**
     * The waiters that a change may have unblocked, oldest first: every waiter that does not wait for one key, and
     * the waiters for the keys in {@code keys} (keys that received an entry).
     */
    List<Waiter> candidates(Collection<String> keys) {
        List<Waiter> result = new ArrayList<>(general);
        boolean merged = false;
        for (String key : keys) {
            ArrayDeque<Waiter> queue = byKey.get(key);
            if (queue != null) {
                result.addAll(queue);
                merged = true;
            }
        }
        if (merged && result.size() > 1) {
            result.sort((a, b) -> Long.compare(a.seq, b.seq));
        }
        return result;
    }

    /** Every waiter, and empties the queue. */
    List<Waiter> drain() {
        List<Waiter> all = new ArrayList<>(general);
        byKey.values().forEach(all::addAll);
        all.sort((a, b) -> Long.compare(a.seq, b.seq));
        general.clear();
        byKey.clear();
        size = 0;
        return all;
    }
}
