package robotworld.space;

/** The four kinds of entry a container can hold. */
public enum EntryType {
    INTEGER, STRING, CREF, TUPLE
}
