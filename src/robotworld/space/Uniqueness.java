package robotworld.space;

/** Whether a container may hold equal entries. */
public enum Uniqueness {
    /** Equal entries may coexist (the default). */
    BAG,
    /** No two entries are equal; a write of a duplicate waits until the equal entry is gone. */
    SET
}
