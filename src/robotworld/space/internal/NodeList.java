package robotworld.space.internal;

/**
 * An intrusive doubly linked list over {@link Node}s, threaded through either the insertion links (oldest
 * first: FIFO from the front, LIFO from the back) or the usage links (least recently used first).
 */
final class NodeList {

    private final boolean byUsage;
    private Node first;
    private Node last;

    private NodeList(boolean byUsage) {
        this.byUsage = byUsage;
    }

    /** Oldest written first. */
    static NodeList byInsertion() {
        return new NodeList(false);
    }

    /** Least recently used first. */
    static NodeList byUsage() {
        return new NodeList(true);
    }

    Node first() {
        return first;
    }

    Node last() {
        return last;
    }

    Node next(Node node) {
        return byUsage ? node.moreRecent : node.newer;
    }

    Node previous(Node node) {
        return byUsage ? node.lessRecent : node.older;
    }

    void append(Node node) {
        setPrevious(node, last);
        setNext(node, null);
        if (last == null) {
            first = node;
        } else {
            setNext(last, node);
        }
        last = node;
    }

    /**
     * Inserts a node that was unlinked earlier back into its old place: after the last node with a smaller stamp
     * ({@code written} or {@code used}, depending on the list). Walks from the back, where restored entries of
     * LIFO and keyed containers usually belong; O(size) at worst, and only used to undo a removal.
     */
    void insertByStamp(Node node) {
        long stamp = stamp(node);
        Node before = last;
        while (before != null && stamp(before) > stamp) {
            before = previous(before);
        }
        Node after = before == null ? first : next(before);
        setPrevious(node, before);
        setNext(node, after);
        if (before == null) {
            first = node;
        } else {
            setNext(before, node);
        }
        if (after == null) {
            last = node;
        } else {
            setPrevious(after, node);
        }
    }

    private long stamp(Node node) {
        return byUsage ? node.used : node.written;
    }

    void unlink(Node node) {
        Node before = previous(node);
        Node after = next(node);
        if (before == null) {
            first = after;
        } else {
            setNext(before, after);
        }
        if (after == null) {
            last = before;
        } else {
            setPrevious(after, before);
        }
        setPrevious(node, null);
        setNext(node, null);
    }

    void moveToEnd(Node node) {
        if (last != node) {
            unlink(node);
            append(node);
        }
    }

    void clear() {
        first = null;
        last = null;
    }

    private void setNext(Node node, Node next) {
        if (byUsage) {
            node.moreRecent = next;
        } else {
            node.newer = next;
        }
    }

    private void setPrevious(Node node, Node previous) {
        if (byUsage) {
            node.lessRecent = previous;
        } else {
            node.older = previous;
        }
    }
}
