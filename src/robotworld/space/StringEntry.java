package robotworld.space;

import java.util.Objects;

/** A string entry. */
public record StringEntry(String value) implements Entry {

    /** @throws NullPointerException if {@code value} is null */
    public StringEntry {
        Objects.requireNonNull(value, "value");
    }

    @Override
    public EntryType type() {
        return EntryType.STRING;
    }

    /** The value in double quotes, with quotes and backslashes escaped, so tuples print unambiguously. */
    @Override
    public String toString() {
        return '"' + value.replace("\\", "\\\\").replace("\"", "\\\"") + '"';
    }
}
