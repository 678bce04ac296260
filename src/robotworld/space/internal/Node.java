package robotworld.space.internal;

import robotworld.space.Entry;

/**
 * One stored entry and its place in every structure of its container. Each structure links the node directly
 * (no wrapper objects), so every order, key and vector operation is O(1).
 */
final class Node {

    final Entry entry;
    /** Unique key in the KEY view, or null. */
    final String key;
    /** Vector position, or -1 when the container has no VECTOR view. */
    final int position;
    /** Insertion stamp: larger = written later. */
    final long written;
    /** LRU stamp: larger = used more recently. */
    long used;

    // insertion list (FIFO/LIFO)
    Node older;
    Node newer;
    // usage list (LRU)
    Node lessRecent;
    Node moreRecent;
    /** Index in the random-access pool. */
    int slot;

    Node(Entry entry, String key, int position, long written) {
        this.entry = entry;
        this.key = key;
        this.position = position;
        this.written = written;
        this.used = written;
    }
}
