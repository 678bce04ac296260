package robotworld.xvsm;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;

/**
 * The layout every request and answer tuple shares, kept as the thesis's tables 4-8 show it: the first field is
 * the requester's key (a string), the last field names the function, and the fields between are the arguments
 * (in a request) or the values (in an answer): {@code <key, fields..., function>}. The function is a string,
 * except for the X10 appliance module whose function code is an integer (table 4).
 *
 * @param key      the requester's key: {@code host#call} for a remote call, the own host name for a published
 *                 local call
 * @param fields   the arguments or values
 * @param function the function name (or code)
 */
public record CallTuple(String key, List<Entry> fields, Entry function) {

    /** Copies the fields. */
    public CallTuple {
        Objects.requireNonNull(key, "key");
        fields = List.copyOf(fields);
        Objects.requireNonNull(function, "function");
    }

    /** A call tuple of plain values, each converted with {@link Entry#from(Object)}. */
    public static CallTuple of(String key, Object function, Object... fields) {
        List<Entry> entries = new ArrayList<>(fields.length);
        for (Object field : fields) {
            entries.add(Entry.from(field));
        }
        return new CallTuple(key, entries, Entry.from(function));
    }

    /** Reads the layout from an entry taken from a container. */
    public static CallTuple parse(Entry entry) {
        if (!(entry instanceof Tuple tuple) || tuple.arity() < 2 || !(tuple.get(0) instanceof StringEntry key)) {
            throw new MalformedCallException("not a <key, ..., function> tuple: " + entry);
        }
        Entry function = tuple.get(tuple.arity() - 1);
        if (!(function instanceof StringEntry || function instanceof IntEntry)) {
            throw new MalformedCallException("the last field is not a function name or code: " + entry);
        }
        return new CallTuple(key.value(), tuple.fields().subList(1, tuple.arity() - 1), function);
    }

    /** The tuple to write: {@code <key, fields..., function>}. */
    public Tuple toTuple() {
        List<Entry> all = new ArrayList<>(fields.size() + 2);
        all.add(Entry.of(key));
        all.addAll(fields);
        all.add(function);
        return new Tuple(all);
    }

    /** This layout under another key (an answer goes back under the requester's key). */
    public CallTuple withKey(String newKey) {
        return new CallTuple(newKey, fields, function);
    }

    /** The same key and function with other fields (the answer to a request). */
    public CallTuple withFields(List<Entry> newFields) {
        return new CallTuple(key, newFields, function);
    }

    /** The function as text: the name, or the code's number. */
    public String functionText() {
        return function instanceof StringEntry name ? name.value() : function.toString();
    }

    /** Whether the function field is this name. */
    public boolean is(String functionName) {
        return function instanceof StringEntry name && name.value().equals(functionName);
    }

    /** Number of fields between key and function. */
    public int size() {
        return fields.size();
    }

    /**
     * Checks the number of fields between key and function.
     *
     * @throws MalformedCallException when it is not {@code count}
     */
    public CallTuple expectFields(int count) {
        if (fields.size() != count) {
            throw new MalformedCallException(functionText() + " takes " + count + " field(s) between key and function, "
                    + this + " has " + fields.size());
        }
        return this;
    }

    /** The exception for a function name or code this module does not have. */
    public MalformedCallException unknownFunction() {
        return new MalformedCallException("unknown function " + function + " in " + this);
    }

    /** Field {@code index} (0 = the one after the key) as an int. */
    public int intAt(int index) {
        Entry field = field(index);
        if (!(field instanceof IntEntry number) || number.value() != (int) number.value()) {
            throw new MalformedCallException("field " + (index + 1) + " of " + this + " is not an int");
        }
        return (int) number.value();
    }

    /** Field {@code index} as a string. */
    public String stringAt(int index) {
        if (!(field(index) instanceof StringEntry text)) {
            throw new MalformedCallException("field " + (index + 1) + " of " + this + " is not a string");
        }
        return text.value();
    }

    /** Field {@code index} as a tuple. */
    public Tuple tupleAt(int index) {
        if (!(field(index) instanceof Tuple tuple)) {
            throw new MalformedCallException("field " + (index + 1) + " of " + this + " is not a tuple");
        }
        return tuple;
    }

    private Entry field(int index) {
        if (index >= fields.size()) {
            throw new MalformedCallException(this + " has no field " + (index + 1));
        }
        return fields.get(index);
    }

    @Override
    public String toString() {
        return toTuple().toString();
    }
}
