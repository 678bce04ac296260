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
