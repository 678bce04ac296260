package robotworld.space.wire;

import java.net.URI;
import java.net.URISyntaxException;
import java.util.List;
import java.util.Set;

import com.fasterxml.jackson.core.JsonFactory;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Template;
import robotworld.space.Timeout;

/**
 * Reads one wire message (see {@code docs/wire.md}) from a byte array, in either of its two forms: JSON, or the
 * compact binary form of the hot operations ({@link BinaryWire}), told apart by the message's first byte. Types and
 * {@link WireLimits} are checked as it goes; every violation is a {@link WireFormatException} naming the offending
 * field. Both forms yield the same field names and values, so a message's reader does not care which it got.
 *
 * <p>Typical use: {@code startObject()}, then {@code while ((field = nextField()) != null) switch (field) ...},
 * then {@code end()}.
 */
public abstract class WireReader implements AutoCloseable {

    WireReader() {
    }

    /** A reader over {@code length} bytes of {@code data} from {@code offset}, of the form they are in. */
    public static WireReader of(JsonFactory factory, WireLimits limits, CrefMapping crefs, byte[] data, int offset,
                                int length) {
        if (length > 0 && data[offset] == BinaryWire.MARKER) {
            return new BinaryWireReader(limits, crefs, data, offset, length);
        }
        return JsonWireReader.open(factory, limits, crefs, data, offset, length);
    }

    // ---- structure ----

    /** Expects the start of an object (in the binary form, of the message or of an object-valued field). */
    public abstract void startObject();

    /** The next field name of the current object, or null at its end. */
    public abstract String nextField();

    /** Expects that nothing follows the message's top-level value. */
    public abstract void end();

    /** Skips the value of the current field. */
    public abstract void skipValue();

    /** Fails for an unknown field; the format is strict so that typos are noticed. */
    public WireFormatException unknownField(String field) {
        return new WireFormatException("unknown field '" + Wire.truncate(field) + "'");
    }

    // ---- scalars ----

    /** A 64-bit integer. */
    public abstract long readLong(String what);

    /** An integer in {@code [min, max]}. */
    public int readInt(String what, int min, int max) {
        long value = readLong(what);
        if (value < min || value > max) {
            throw new WireFormatException(what + " must be in " + min + ".." + max + "; was " + value);
        }
        return (int) value;
    }

    /** A string of at most the string limit. */
    public abstract String readString(String what);

    /** A string, or null for JSON null. */
    public abstract String readNullableString(String what);

    /** true or false. */
    public abstract boolean readBoolean(String what);

    /** A timeout in milliseconds: -1 (infinite), 0 (try once) or more. */
    public Timeout readTimeout() {
        long millis = readLong("timeout");
        if (millis < -1) {
            throw new WireFormatException("timeout must be -1 (infinite), 0 (try once) or positive; was " + millis);
        }
        return Timeout.ofMillis(millis);
    }

    /** A list of strings (at most {@code max}). */
    public abstract List<String> readStrings(String what, int max);

    // ---- entries and the rest ----

    /** One entry: integer, string, cref or tuple. */
    public abstract Entry readEntry();

    /** A list of entries. */
    public abstract List<Entry> readEntries(String what);

    /** A cref. */
    public abstract ContainerRef readCref();

    /** The items of a write or shift. */
    public abstract List<Item> readItems();

    /** A template. */
    public abstract Template readTemplate();

    /** The selectors of a read, take or destroy. */
    public abstract Selector[] readSelectors();

    /** A container spec. */
    public abstract ContainerSpec readSpec();

    /** A list of operation names. */
    public abstract Set<Operation> readOperations();

    /** A notification mode name. */
    public NotificationMode readMode() {
        return Wire.mode(readString("mode"));
    }

    /** An operation name. */
    public Operation readOperation() {
        return Wire.operation(readString("operation"));
    }

    @Override
    public abstract void close();

    // ---- shared by both forms ----

    /** A selector of the one kind that was given (the others null); a value the space refuses is a format error. */
    static Selector selector(Order order, String key, Integer index, Template template, int count) {
        try {
            if (order != null) {
                return Selector.order(order, count);
            }
            if (key != null) {
                return Selector.key(key, count);
            }
            if (index != null) {
                return Selector.vector(index, count);
            }
            return Selector.template(template, count);
        } catch (IllegalArgumentException e) {
            throw new WireFormatException(e.getMessage());
        }
    }

    /** A cref read from the wire, checked and translated to the space's own form. */
    static ContainerRef cref(CrefMapping crefs, String id, String space) {
        if (id.isBlank()) {
            throw new WireFormatException("a cref's id must not be blank");
        }
        try {
            return crefs.incoming(new ContainerRef(spaceUri(space), id));
        } catch (URISyntaxException e) {
            throw new WireFormatException("a cref's space is not a URI: " + Wire.truncate(space));
        }
    }

    /** The last space URI parsed (nearly every cref names the same space), so it is parsed once, not per request. */
    private static volatile URI lastSpace;

    private static URI spaceUri(String text) throws URISyntaxException {
        URI last = lastSpace;
        if (last != null && last.toString().equals(text)) {
            return last;
        }
        URI parsed = new URI(text);
        lastSpace = parsed;
        return parsed;
    }
}
