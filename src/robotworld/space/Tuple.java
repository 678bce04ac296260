package robotworld.space;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.StringJoiner;

/**
 * An ordered, immutable sequence of entries; fields may be tuples themselves. The number of fields is the
 * tuple's arity.
 */
public record Tuple(List<Entry> fields) implements Entry {

    /** Copies {@code fields}; @throws NullPointerException if it or any field is null. */
    public Tuple {
        fields = List.copyOf(fields);
    }

    /** A tuple of the given entries. */
    public static Tuple of(Entry... fields) {
        return new Tuple(List.of(fields));
    }

    /** A tuple of plain Java values, each converted with {@link Entry#from(Object)}. */
    public static Tuple of(Object... values) {
        List<Entry> fields = new ArrayList<>(values.length);
        for (Object value : values) {
            fields.add(Entry.from(value));
        }
        return new Tuple(fields);
    }

    @Override
    public EntryType type() {
        return EntryType.TUPLE;
    }

    /** Number of fields. */
    public int arity() {
        return fields.size();
    }

    /** Field {@code index} (0-based). */
    public Entry get(int index) {
        return fields.get(index);
    }

    /** Field {@code index} as a long; @throws ClassCastException if it is not an integer. */
    public long longAt(int index) {
        return ((IntEntry) fields.get(index)).value();
    }

    /** Field {@code index} as a string; @throws ClassCastException if it is not a string. */
    public String stringAt(int index) {
        return ((StringEntry) fields.get(index)).value();
    }

    /** Field {@code index} as a tuple; @throws ClassCastException if it is not a tuple. */
    public Tuple tupleAt(int index) {
        return (Tuple) fields.get(index);
    }

    /** Field {@code index} as a container reference; @throws ClassCastException if it is not a cref. */
    public ContainerRef crefAt(int index) {
        return (ContainerRef) fields.get(index);
    }

    @Override
    public String toString() {
        StringJoiner joined = new StringJoiner(", ", "<", ">");
        for (Entry field : fields) {
            joined.add(Objects.toString(field));
        }
        return joined.toString();
    }
}
