package robotworld.space;

import java.util.Objects;

/**
 * Chooses the entries an operation works on. Every selector carries a count: how many entries it must find
 * (the operation waits until that many exist) or {@link #ALL}: every matching entry present at that moment,
 * possibly none, without ever waiting.
 *
 * <p>Several selectors may be chained in one operation: the first chooses from the container, each further
 * one chooses from what the previous one chose.
 */
public sealed interface Selector permits Selector.Ordered, Selector.Key, Selector.Vector, Selector.Matching {

    /** Count meaning "every matching entry present now, possibly none; never wait". */
    int ALL = -1;

    /** How many entries this selector needs, or {@link #ALL}. */
    int count();

    /** The {@code count} first entries in {@code order}. */
    static Selector order(Order order, int count) {
        return new Ordered(order, count);
    }

    /** The oldest entry. */
    static Selector fifo() {
        return new Ordered(Order.FIFO, 1);
    }

    /** The {@code count} oldest entries, oldest first. */
    static Selector fifo(int count) {
        return new Ordered(Order.FIFO, count);
    }

    /** The newest entry. */
    static Selector lifo() {
        return new Ordered(Order.LIFO, 1);
    }

    /** The {@code count} newest entries, newest first. */
    static Selector lifo(int count) {
        return new Ordered(Order.LIFO, count);
    }

    /** The least recently used entry. */
    static Selector lru() {
        return new Ordered(Order.LRU, 1);
    }

    /** The {@code count} least recently used entries, least recent first. */
    static Selector lru(int count) {
        return new Ordered(Order.LRU, count);
    }

    /** One entry chosen at random. */
    static Selector random() {
        return new Ordered(Order.RANDOM, 1);
    }

    /** {@code count} distinct entries chosen at random. */
    static Selector random(int count) {
        return new Ordered(Order.RANDOM, count);
    }

    /** The entry stored under {@code key} (container needs a KEY view). */
    static Selector key(String key) {
        return new Key(key, 1);
    }

    /** The entry stored under {@code key}, or none if absent without waiting ({@code count} 1 or {@link #ALL}). */
    static Selector key(String key, int count) {
        return new Key(key, count);
    }

    /** The entry at vector position {@code index} (container needs a VECTOR view). */
    static Selector vector(int index) {
        return new Vector(index, 1);
    }

    /**
     * The entries at positions {@code index .. index+count-1} (all must be occupied), or with {@link #ALL} every
     * entry at a position {@code >= index}, in position order.
     */
    static Selector vector(int index, int count) {
        return new Vector(index, count);
    }

    /** The first entry matching {@code template}, in the container's base order. */
    static Selector template(Template template) {
        return new Matching(template, 1);
    }

    /** The first {@code count} entries matching {@code template}, in the container's base order. */
    static Selector template(Template template, int count) {
        return new Matching(template, count);
    }

    private static int checkCount(int count) {
        if (count < 1 && count != ALL) {
            throw new IllegalArgumentException("count must be at least 1, or ALL; was " + count);
        }
        return count;
    }

    /** Selection by one of the four orders, independent of the container's base order. */
    record Ordered(Order order, int count) implements Selector {
        public Ordered {
            Objects.requireNonNull(order, "order");
            checkCount(count);
        }
    }

    /** Selection by key; keys are unique, so the count is 1 (wait for it) or ALL (take it if present). */
    record Key(String key, int count) implements Selector {
        public Key {
            Objects.requireNonNull(key, "key");
            if (count != 1 && count != ALL) {
                throw new IllegalArgumentException("a key selects one entry: count must be 1 or ALL; was " + count);
            }
        }
    }

    /** Selection by vector position. */
    record Vector(int index, int count) implements Selector {
        public Vector {
            if (index < 0) {
                throw new IllegalArgumentException("vector index must not be negative; was " + index);
            }
            checkCount(count);
        }
    }

    /** Selection by template, results in the container's base order. */
    record Matching(Template template, int count) implements Selector {
        public Matching {
            Objects.requireNonNull(template, "template");
            checkCount(count);
        }
    }
}
