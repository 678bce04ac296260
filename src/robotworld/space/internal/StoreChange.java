package robotworld.space.internal;

/**
 * One change to the entries of a {@link ContainerContents}, as reported to its observer. Replaying the same
 * changes, in the same order, on a copy ({@link ContainerContents#apply}) makes the copy identical.
 */
public sealed interface StoreChange {

    /** An entry was written, shifted in, or put back after a removal was undone. */
    record Placed(PlacedEntry entry) implements StoreChange {
    }

    /** The entry with this insertion stamp was taken, destroyed or displaced. */
    record Removed(long written) implements StoreChange {
    }

    /** The entry with this insertion stamp was read: it is now the most recently used. */
    record Touched(long written, long used) implements StoreChange {
    }
}
