package robotworld.space.wire;

import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.Item;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.StringEntry;
import robotworld.space.Template;
import robotworld.space.Tuple;

/**
 * The binary form of {@link WireWriter} ({@link BinaryWire}): the message is built in an array of its own and handed
 * to the output stream at {@link #close()}. Only the fields of the hot operations can be written; the others are a
 * programming error (such messages go as JSON).
 */
final class BinaryWireWriter extends WireWriter {

    private final CrefMapping crefs;
    private final OutputStream out;
    private byte[] bytes = new byte[128];
    private int length;
    private int openObjects;
    private boolean closed;

    BinaryWireWriter(CrefMapping crefs, OutputStream out) {
        this.crefs = crefs;
        this.out = out;
    }

    @Override
    public WireWriter startObject() {
        if (openObjects++ == 0 && length == 0) {
            put(BinaryWire.MARKER);
        }
        return this;
    }

    @Override
    public WireWriter endObject() {
        openObjects--;
        put(0);
        return this;
    }

    @Override
    public WireWriter field(String name) {
        code(name, BinaryWire.Kind.OBJECT);
        return this;
    }

    @Override
    public WireWriter field(String name, String value) {
        code(name, BinaryWire.Kind.STRING);
        string(value);
        return this;
    }

    @Override
    public WireWriter field(String name, long value) {
        code(name, BinaryWire.Kind.LONG);
        signed(value);
        return this;
    }

    @Override
    public WireWriter field(String name, boolean value) {
        code(name, BinaryWire.Kind.BOOLEAN);
        put(value ? 1 : 0);
        return this;
    }

    @Override
    public WireWriter strings(String name, Collection<String> values) {
        throw notCarried(name);
    }

    @Override
    public WireWriter entry(Entry entry) {
        writeEntry(entry);
        return this;
    }

    @Override
    public WireWriter entries(String name, List<Entry> entries) {
        code(name, BinaryWire.Kind.ENTRIES);
        unsigned(entries.size());
        for (Entry entry : entries) {
            writeEntry(entry);
        }
        return this;
    }

    private void writeEntry(Entry entry) {
        if (entry instanceof IntEntry integer) {
            put(BinaryWire.ENTRY_LONG);
            signed(integer.value());
        } else if (entry instanceof StringEntry text) {
            put(BinaryWire.ENTRY_STRING);
            string(text.value());
        } else if (entry instanceof Tuple tuple) {
            put(BinaryWire.ENTRY_TUPLE);
            unsigned(tuple.fields().size());
            for (Entry field : tuple.fields()) {
                writeEntry(field);
            }
        } else {
            put(BinaryWire.ENTRY_CREF);
            writeCref((ContainerRef) entry);
        }
    }

    @Override
    public WireWriter cref(String name, ContainerRef ref) {
        code(name, BinaryWire.Kind.CREF);
        writeCref(ref);
        return this;
    }

    private void writeCref(ContainerRef ref) {
        ContainerRef sent = crefs.outgoing(ref);
        string(sent.id());
        string(sent.space().toString());
    }

    @Override
    public WireWriter items(List<Item> items) {
        code("items", BinaryWire.Kind.ITEMS);
        unsigned(items.size());
        for (Item item : items) {
            writeEntry(item.entry());
            put((item.key() != null ? BinaryWire.ITEM_KEY : 0) | (item.hasIndex() ? BinaryWire.ITEM_INDEX : 0));
            if (item.key() != null) {
                string(item.key());
            }
            if (item.hasIndex()) {
                unsigned(item.index());
            }
        }
        return this;
    }

    @Override
    public WireWriter selectors(Selector[] selectors) {
        code("selectors", BinaryWire.Kind.SELECTORS);
        unsigned(selectors.length);
        for (Selector selector : selectors) {
            if (selector instanceof Selector.Ordered ordered) {
                put(BinaryWire.SELECTOR_ORDER);
                put(orderCode(ordered.order()));
            } else if (selector instanceof Selector.Key byKey) {
                put(BinaryWire.SELECTOR_KEY);
                string(byKey.key());
            } else if (selector instanceof Selector.Vector byPosition) {
                put(BinaryWire.SELECTOR_VECTOR);
                unsigned(byPosition.index());
            } else {
                put(BinaryWire.SELECTOR_TEMPLATE);
                writeTemplate(((Selector.Matching) selector).template());
            }
            unsigned(selector.count() == Selector.ALL ? 0 : selector.count());
        }
        return this;
    }

    private static int orderCode(Order order) {
        return switch (order) {
            case RANDOM -> 0;
            case FIFO -> 1;
            case LIFO -> 2;
            case LRU -> 3;
        };
    }

    private void writeTemplate(Template template) {
        if (template instanceof Template.Any) {
            put(BinaryWire.TEMPLATE_ANY);
        } else if (template instanceof Template.OfType type) {
            put(BinaryWire.TEMPLATE_TYPE);
            put(switch (type.type()) {
                case INTEGER -> 1;
                case STRING -> 2;
                case CREF -> 3;
                case TUPLE -> 4;
            });
        } else if (template instanceof Template.Value value) {
            put(BinaryWire.TEMPLATE_VALUE);
            writeEntry(value.value());
        } else {
            List<Template> fields = ((Template.TupleOf) template).fields();
            put(BinaryWire.TEMPLATE_TUPLE);
            unsigned(fields.size());
            for (Template field : fields) {
                writeTemplate(field);
            }
        }
    }

    @Override
    public WireWriter spec(String name, ContainerSpec spec) {
        throw notCarried(name);
    }

    @Override
    public WireWriter operations(Collection<Operation> operations) {
        throw notCarried("operations");
    }

    @Override
    public void flush() {
        // the message goes out whole at close()
    }

    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        try {
            out.write(bytes, 0, length);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    // ---- low level ----

    private void code(String name, BinaryWire.Kind kind) {
        int code = BinaryWire.code(name);
        if (code == 0 || BinaryWire.FIELDS.get(code - 1).kind() != kind) {
            throw notCarried(name);
        }
        put(code);
    }

    private static IllegalStateException notCarried(String what) {
        return new IllegalStateException(what + " is not carried in the binary form; this message must go as JSON");
    }

    private void put(int b) {
        if (length == bytes.length) {
            bytes = Arrays.copyOf(bytes, length * 2);
        }
        bytes[length++] = (byte) b;
    }

    private void unsigned(long value) {
        while ((value & ~0x7FL) != 0) {
            put((int) ((value & 0x7F) | 0x80));
            value >>>= 7;
        }
        put((int) value);
    }

    private void signed(long value) {
        unsigned((value << 1) ^ (value >> 63));
    }

    private void string(String text) {
        int chars = text.length();
        boolean ascii = true;
        for (int i = 0; i < chars; i++) {
            if (text.charAt(i) >= 0x80) {
                ascii = false;
                break;
            }
        }
        if (ascii) {
            unsigned(chars);
            ensure(chars);
            for (int i = 0; i < chars; i++) {
                bytes[length++] = (byte) text.charAt(i); // ASCII: one byte per char
            }
        } else {
            byte[] utf8 = text.getBytes(StandardCharsets.UTF_8);
            unsigned(utf8.length);
            ensure(utf8.length);
            System.arraycopy(utf8, 0, bytes, length, utf8.length);
            length += utf8.length;
        }
    }

    private void ensure(int more) {
        if (length + more > bytes.length) {
            bytes = Arrays.copyOf(bytes, Math.max(bytes.length * 2, length + more));
        }
    }
}
