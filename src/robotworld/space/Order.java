package robotworld.space;

/** The orders in which entries can be chosen; every container has one of them as its base order. */
public enum Order {
    /** Any entry, chosen at random. The thesis's default. */
    RANDOM,
    /** Oldest written first (a queue). */
    FIFO,
    /** Newest written first (a stack). */
    LIFO,
    /** The entry not written or read for the longest time first. */
    LRU
}
