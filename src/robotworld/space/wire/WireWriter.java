package robotworld.space.wire;

import java.io.OutputStream;
import java.util.Collection;
import java.util.List;

import com.fasterxml.jackson.core.JsonFactory;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Operation;
import robotworld.space.Selector;

/**
 * Writes one wire message (see {@code docs/wire.md}): entries, items, templates, selectors and specs, plus plain
 * fields, as JSON ({@link #to}) or in the compact binary form of the hot operations ({@link #binary}; only the fields
 * those carry, {@link BinaryWire}). Call {@link #close()} at the end.
 */
public abstract class WireWriter implements AutoCloseable {

    WireWriter() {
    }

    /** A JSON writer onto {@code out} (not closed by {@link #close()}). */
    public static WireWriter to(JsonFactory factory, CrefMapping crefs, OutputStream out) {
        return JsonWireWriter.open(factory, crefs, out);
    }

    /** A writer of the binary form onto {@code out}, which gets the bytes at {@link #close()} (and is not closed). */
    public static WireWriter binary(CrefMapping crefs, OutputStream out) {
        return new BinaryWireWriter(crefs, out);
    }

    /** Starts an object: the message, or the value of the field just named. */
    public abstract WireWriter startObject();

    /** Ends the object started last. */
    public abstract WireWriter endObject();

    /** Names a field whose value follows (an object). */
    public abstract WireWriter field(String name);

    /** A string field. */
    public abstract WireWriter field(String name, String value);

    /** An integer field. */
    public abstract WireWriter field(String name, long value);

    /** A boolean field. */
    public abstract WireWriter field(String name, boolean value);

    /** A field holding a list of strings. */
    public abstract WireWriter strings(String name, Collection<String> values);

    /** One entry as a value. */
    public abstract WireWriter entry(Entry entry);

    /** A field holding a list of entries. */
    public abstract WireWriter entries(String name, List<Entry> entries);

    /** A cref field, translated to its wire form. */
    public abstract WireWriter cref(String name, ContainerRef ref);

    /** The {@code items} field of a write or shift. */
    public abstract WireWriter items(List<Item> items);

    /** The {@code selectors} field of a read, take or destroy. */
    public abstract WireWriter selectors(Selector[] selectors);

    /** A container spec field. */
    public abstract WireWriter spec(String name, ContainerSpec spec);

    /** The {@code operations} field of a subscription. */
    public abstract WireWriter operations(Collection<Operation> operations);

    /** Pushes what was written to the output stream. */
    public abstract void flush();

    @Override
    public abstract void close();
}
