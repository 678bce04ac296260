package robotworld.space.wire;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.EntryType;
import robotworld.space.IntEntry;
import robotworld.space.Item;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.StringEntry;
import robotworld.space.Template;
import robotworld.space.Tuple;

/** The binary form of {@link WireReader} ({@link BinaryWire}): a cursor over the message's bytes. */
final class BinaryWireReader extends WireReader {

    private static final Order[] ORDERS = {Order.RANDOM, Order.FIFO, Order.LIFO, Order.LRU};
    private static final EntryType[] TYPES = {EntryType.INTEGER, EntryType.STRING, EntryType.CREF, EntryType.TUPLE};
    private static final int MAX_OBJECTS = 2; // the message and a take in it

    private final WireLimits limits;
    private final CrefMapping crefs;
    private final byte[] data;
    private final int end;
    private int position;
    /** Per open object, the codes of the fields it had so far (bit per code). */
    private final long[] seen = new long[MAX_OBJECTS];
    private int openObjects;
    private boolean started;
    /** The field whose value is next. */
    private BinaryWire.Field field;

    BinaryWireReader(WireLimits limits, CrefMapping crefs, byte[] data, int offset, int length) {
        this.limits = limits;
        this.crefs = crefs;
        this.data = data;
        this.position = offset;
        this.end = offset + length;
    }

    // ---- structure ----

    @Override
    public void startObject() {
        if (!started) {
            started = true;
            if (readByte() != BinaryWire.MARKER) {
                throw new WireFormatException("a binary message starts with 0xB1");
            }
        } else if (field == null || field.kind() != BinaryWire.Kind.OBJECT) {
            throw new WireFormatException("expected an object here");
        }
        if (openObjects == MAX_OBJECTS) {
            throw new WireFormatException("objects nest deeper than " + MAX_OBJECTS);
        }
        seen[openObjects++] = 0;
        field = null;
    }

    @Override
    public String nextField() {
        if (openObjects == 0) {
            throw new WireFormatException("no object is open");
        }
        int code = readByte() & 0xFF;
        if (code == 0) {
            openObjects--;
            field = null;
            return null;
        }
        if (code > BinaryWire.FIELDS.size()) {
            throw new WireFormatException("unknown field code " + code);
        }
        long bit = 1L << code;
        if ((seen[openObjects - 1] & bit) != 0) {
            throw new WireFormatException("field '" + BinaryWire.FIELDS.get(code - 1).name() + "' appears twice");
        }
        seen[openObjects - 1] |= bit;
        field = BinaryWire.FIELDS.get(code - 1);
        return field.name();
    }

    @Override
    public void end() {
        if (openObjects != 0 || !started) {
            throw new WireFormatException("the message ends inside an object");
        }
        if (position != end) {
            throw new WireFormatException("unexpected content after the message: " + (end - position) + " bytes");
        }
    }

    @Override
    public void skipValue() {
        switch (expectField().kind()) {
            case CREF -> readCref();
            case LONG -> readLong("value");
            case SELECTORS -> readSelectors();
            case ITEMS -> readItems();
            case STRING -> readString("value");
            case ENTRIES -> readEntries("value");
            case BOOLEAN -> readBoolean("value");
            case OBJECT -> {
                startObject();
                while (nextField() != null) {
                    skipValue();
                }
            }
            default -> throw new IllegalStateException();
        }
    }

    // ---- scalars ----

    @Override
    public long readLong(String what) {
        expect(BinaryWire.Kind.LONG, what);
        return signed();
    }

    @Override
    public String readString(String what) {
        expect(BinaryWire.Kind.STRING, what);
        return string(what);
    }

    @Override
    public String readNullableString(String what) {
        return readString(what);
    }

    @Override
    public boolean readBoolean(String what) {
        expect(BinaryWire.Kind.BOOLEAN, what);
        int value = readByte();
        if (value != 0 && value != 1) {
            throw new WireFormatException(what + " must be 0 or 1, found " + value);
        }
        return value == 1;
    }

    @Override
    public List<String> readStrings(String what, int max) {
        throw notCarried(what);
    }

    // ---- entries and the rest ----

    @Override
    public Entry readEntry() {
        return entry(0);
    }

    @Override
    public List<Entry> readEntries(String what) {
        expect(BinaryWire.Kind.ENTRIES, what);
        int count = count(what, Integer.MAX_VALUE);
        List<Entry> entries = new ArrayList<>(Math.min(count, 16));
        for (int i = 0; i < count; i++) {
            entries.add(entry(0));
        }
        return entries;
    }

    private Entry entry(int depth) {
        int tag = readByte();
        switch (tag) {
            case BinaryWire.ENTRY_LONG:
                return new IntEntry(signed());
            case BinaryWire.ENTRY_STRING:
                return new StringEntry(string("string entry"));
            case BinaryWire.ENTRY_TUPLE: {
                if (depth + 1 > limits.maxDepth()) {
                    throw new WireFormatException("tuples nest deeper than " + limits.maxDepth());
                }
                int arity = count("tuple", Integer.MAX_VALUE);
                List<Entry> fields = new ArrayList<>(Math.min(arity, 16));
                for (int i = 0; i < arity; i++) {
                    fields.add(entry(depth + 1));
                }
                return new Tuple(fields);
            }
            case BinaryWire.ENTRY_CREF:
                return cref();
            default:
                throw new WireFormatException("unknown entry tag " + tag);
        }
    }

    @Override
    public ContainerRef readCref() {
        expect(BinaryWire.Kind.CREF, "container");
        return cref();
    }

    private ContainerRef cref() {
        String id = string("cref");
        String space = string("space");
        return cref(crefs, id, space);
    }

    @Override
    public List<Item> readItems() {
        expect(BinaryWire.Kind.ITEMS, "items");
        int count = count("items", limits.maxItems());
        List<Item> items = new ArrayList<>(Math.min(count, 16));
        for (int i = 0; i < count; i++) {
            Entry entry = entry(0);
            int flags = readByte();
            if ((flags & ~(BinaryWire.ITEM_KEY | BinaryWire.ITEM_INDEX)) != 0) {
                throw new WireFormatException("unknown item flags " + flags);
            }
            String key = (flags & BinaryWire.ITEM_KEY) != 0 ? string("key") : null;
            int index = Item.APPEND;
            if ((flags & BinaryWire.ITEM_INDEX) != 0) {
                index = intIn("index", 0, Integer.MAX_VALUE);
            }
            items.add(new Item(entry, key, index));
        }
        return items;
    }

    @Override
    public Template readTemplate() {
        return template(0);
    }

    private Template template(int depth) {
        int kind = readByte();
        switch (kind) {
            case BinaryWire.TEMPLATE_ANY:
                return Template.ANY;
            case BinaryWire.TEMPLATE_TYPE: {
                int type = readByte();
                if (type < 1 || type > TYPES.length) {
                    throw new WireFormatException("unknown entry type code " + type);
                }
                return Template.type(TYPES[type - 1]);
            }
            case BinaryWire.TEMPLATE_VALUE:
                return Template.value(entry(0));
            case BinaryWire.TEMPLATE_TUPLE: {
                if (depth + 1 > limits.maxDepth()) {
                    throw new WireFormatException("tuple templates nest deeper than " + limits.maxDepth());
                }
                int arity = count("tuple template", Integer.MAX_VALUE);
                List<Template> fields = new ArrayList<>(Math.min(arity, 16));
                for (int i = 0; i < arity; i++) {
                    fields.add(template(depth + 1));
                }
                return new Template.TupleOf(fields);
            }
            default:
                throw new WireFormatException("unknown template kind " + kind);
        }
    }

    @Override
    public Selector[] readSelectors() {
        expect(BinaryWire.Kind.SELECTORS, "selectors");
        int count = count("selectors", limits.maxSelectors());
        Selector[] selectors = new Selector[count];
        for (int i = 0; i < count; i++) {
            selectors[i] = selector();
        }
        return selectors;
    }

    private Selector selector() {
        int kind = readByte();
        Order order = null;
        String key = null;
        Integer index = null;
        Template template = null;
        switch (kind) {
            case BinaryWire.SELECTOR_ORDER -> {
                int code = readByte();
                if (code < 0 || code >= ORDERS.length) {
                    throw new WireFormatException("unknown order code " + code);
                }
                order = ORDERS[code];
            }
            case BinaryWire.SELECTOR_KEY -> key = string("key");
            case BinaryWire.SELECTOR_VECTOR -> index = intIn("vector", 0, Integer.MAX_VALUE);
            case BinaryWire.SELECTOR_TEMPLATE -> template = template(0);
            default -> throw new WireFormatException("unknown selector kind " + kind);
        }
        long wanted = unsigned();
        if (wanted < 0 || wanted > limits.maxCount()) {
            throw new WireFormatException("count must be \"all\" or in 1.." + limits.maxCount() + "; was " + wanted);
        }
        return selector(order, key, index, template, wanted == 0 ? Selector.ALL : (int) wanted);
    }

    @Override
    public ContainerSpec readSpec() {
        throw notCarried("spec");
    }

    @Override
    public Set<Operation> readOperations() {
        throw notCarried("operations");
    }

    @Override
    public void close() {
        // nothing held
    }

    // ---- low level ----

    private BinaryWire.Field expectField() {
        if (field == null) {
            throw new WireFormatException("a value without its field");
        }
        return field;
    }

    private void expect(BinaryWire.Kind kind, String what) {
        if (expectField().kind() != kind) {
            throw new WireFormatException(what + ": field '" + field.name() + "' does not hold that");
        }
    }

    private static WireFormatException notCarried(String what) {
        return new WireFormatException(what + " is not carried in the binary form; send this request as JSON");
    }

    private int readByte() {
        if (position >= end) {
            throw new WireFormatException("the message ends too soon");
        }
        return data[position++];
    }

    private long unsigned() {
        long value = 0;
        for (int shift = 0; shift < 64; shift += 7) {
            int b = readByte();
            value |= (long) (b & 0x7F) << shift;
            if ((b & 0x80) == 0) {
                if (shift == 63 && (b & 0x7F) > 1) {
                    break; // more than 64 bits
                }
                return value;
            }
        }
        throw new WireFormatException("a number has more than 64 bits");
    }

    private long signed() {
        long zigzag = unsigned();
        return (zigzag >>> 1) ^ -(zigzag & 1);
    }

    private int intIn(String what, int min, int max) {
        long value = unsigned();
        if (value < min || value > max) {
            throw new WireFormatException(what + " must be in " + min + ".." + max + "; was " + value);
        }
        return (int) value;
    }

    /** A count of things that follow, each at least a byte: at most {@code max} and what is left of the message. */
    private int count(String what, int max) {
        long count = unsigned();
        if (count < 0 || count > max) {
            throw new WireFormatException("more than " + max + " " + what + " in one request");
        }
        if (count > end - position) {
            throw new WireFormatException(what + ": " + count + " announced, but the message ends too soon");
        }
        return (int) count;
    }

    private String string(String what) {
        long length = unsigned();
        if (length < 0 || length > end - position) {
            throw new WireFormatException(what + ": the message ends inside a string");
        }
        int bytes = (int) length;
        if (bytes > 4L * limits.maxStringChars()) {
            throw new WireFormatException(what + ": longer than " + limits.maxStringChars() + " characters");
        }
        String text = ascii(bytes) ? new String(data, position, bytes, StandardCharsets.ISO_8859_1) : utf8(bytes, what);
        position += bytes;
        if (text.length() > limits.maxStringChars()) {
            throw new WireFormatException(what + ": longer than " + limits.maxStringChars() + " characters");
        }
        return text;
    }

    private boolean ascii(int bytes) {
        for (int i = position; i < position + bytes; i++) {
            if (data[i] < 0) {
                return false;
            }
        }
        return true;
    }

    private String utf8(int bytes, String what) {
        try {
            return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(data, position, bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new WireFormatException(what + ": not UTF-8");
        }
    }
}
