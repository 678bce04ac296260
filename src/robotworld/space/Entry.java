package robotworld.space;

import java.util.List;

/**
 * A value stored in a container: an integer, a string, a container reference or a tuple.
 *
 * <p>Entries are immutable values compared by content, so they can be used as keys, sent over a wire and
 * shared between threads freely.
 */
public sealed interface Entry permits IntEntry, StringEntry, ContainerRef, Tuple {

    /** The kind of value, as used by type fields of a {@link Template}. */
    EntryType type();

    /** An integer entry. */
    static IntEntry of(long value) {
        return new IntEntry(value);
    }

    /** A string entry. */
    static StringEntry of(String value) {
        return new StringEntry(value);
    }

    /**
     * Converts a plain Java value into an entry: {@code Long}, {@code Integer}, {@code Short} and {@code Byte}
     * become integers, {@code String} a string, a {@code List} or {@code Object[]} a tuple (converted field by
     * field), and an {@code Entry} is returned unchanged.
     *
     * @throws IllegalArgumentException for {@code null} or any other type
     */
    static Entry from(Object value) {
        if (value instanceof Entry entry) {
            return entry;
        }
        if (value instanceof Long || value instanceof Integer || value instanceof Short || value instanceof Byte) {
            return new IntEntry(((Number) value).longValue());
        }
        if (value instanceof String text) {
            return new StringEntry(text);
        }
        if (value instanceof List<?> list) {
            return Tuple.of(list.toArray());
        }
        if (value instanceof Object[] array) {
            return Tuple.of(array);
        }
        throw new IllegalArgumentException("cannot make an entry from "
                + (value == null ? "null" : value.getClass().getName()));
    }
}
