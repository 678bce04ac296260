package robotworld.space;

/** A 64-bit integer entry. */
public record IntEntry(long value) implements Entry {

    @Override
    public EntryType type() {
        return EntryType.INTEGER;
    }

    @Override
    public String toString() {
        return Long.toString(value);
    }
}
