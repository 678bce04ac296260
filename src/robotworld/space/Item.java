package robotworld.space;

import java.util.Objects;

/**
 * An entry to write or shift, together with where it goes in the container's views: an optional key (KEY view)
 * and an optional vector position (VECTOR view). Without a position, a VECTOR container appends the entry.
 *
 * @param entry the value
 * @param key   unique key, or {@code null}
 * @param index vector position ({@code >= 0}), or {@code -1} to append
 */
public record Item(Entry entry, String key, int index) {

    /** Index value meaning "append at the end of the vector". */
    public static final int APPEND = -1;

    /** Validates the fields. */
    public Item {
        Objects.requireNonNull(entry, "entry");
        if (index < APPEND) {
            throw new IllegalArgumentException("vector index must not be negative; was " + index);
        }
    }

    /** An entry with no key and no explicit position. */
    public static Item of(Entry entry) {
        return new Item(entry, null, APPEND);
    }

    /** An entry stored under {@code key}. */
    public static Item keyed(String key, Entry entry) {
        return new Item(entry, Objects.requireNonNull(key, "key"), APPEND);
    }

    /** An entry at vector position {@code position}. */
    public static Item at(int position, Entry entry) {
        if (position < 0) {
            throw new IllegalArgumentException("vector index must not be negative; was " + position);
        }
        return new Item(entry, null, position);
    }

    /** This item stored under {@code newKey} too. */
    public Item withKey(String newKey) {
        return new Item(entry, Objects.requireNonNull(newKey, "key"), index);
    }

    /** This item at vector position {@code position}. */
    public Item atIndex(int position) {
        if (position < 0) {
            throw new IllegalArgumentException("vector index must not be negative; was " + position);
        }
        return new Item(entry, key, position);
    }

    /** Whether the item names a vector position. */
    public boolean hasIndex() {
        return index != APPEND;
    }
}
