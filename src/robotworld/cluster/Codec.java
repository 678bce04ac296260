package robotworld.cluster;

import java.io.IOException;
import java.net.URI;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.UUID;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;

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
import robotworld.space.Uniqueness;
import robotworld.space.internal.PlacedEntry;

/**
 * The binary encoding of the space's values between members: entries, templates, selectors, items, specs and
 * placed entries. Each value starts with a one-byte tag; nothing here uses Java serialization.
 */
final class Codec {

    private static final byte INTEGER = 0;
    private static final byte STRING = 1;
    private static final byte CREF = 2;
    private static final byte TUPLE = 3;

    private static final byte ANY = 0;
    private static final byte OF_TYPE = 1;
    private static final byte VALUE = 2;
    private static final byte TUPLE_OF = 3;

    private static final byte ORDERED = 0;
    private static final byte KEY = 1;
    private static final byte VECTOR = 2;
    private static final byte MATCHING = 3;

    private Codec() {
    }

    // ---- entries ----

    static void writeEntry(ObjectDataOutput out, Entry entry) throws IOException {
        if (entry instanceof IntEntry number) {
            out.writeByte(INTEGER);
            out.writeLong(number.value());
        } else if (entry instanceof StringEntry text) {
            out.writeByte(STRING);
            out.writeString(text.value());
        } else if (entry instanceof ContainerRef ref) {
            out.writeByte(CREF);
            out.writeString(ref.space().toString());
            out.writeString(ref.id());
        } else {
            Tuple tuple = (Tuple) entry;
            out.writeByte(TUPLE);
            out.writeInt(tuple.arity());
            for (Entry field : tuple.fields()) {
                writeEntry(out, field);
            }
        }
    }

    static Entry readEntry(ObjectDataInput in) throws IOException {
        byte tag = in.readByte();
        return switch (tag) {
            case INTEGER -> new IntEntry(in.readLong());
            case STRING -> new StringEntry(in.readString());
            case CREF -> new ContainerRef(URI.create(in.readString()), in.readString());
            case TUPLE -> {
                int arity = in.readInt();
                List<Entry> fields = new ArrayList<>(arity);
                for (int i = 0; i < arity; i++) {
                    fields.add(readEntry(in));
                }
                yield new Tuple(fields);
            }
            default -> throw new IOException("unknown entry tag " + tag);
        };
    }

    static void writeEntries(ObjectDataOutput out, List<Entry> entries) throws IOException {
        out.writeInt(entries.size());
        for (Entry entry : entries) {
            writeEntry(out, entry);
        }
    }

    static List<Entry> readEntries(ObjectDataInput in) throws IOException {
        int size = in.readInt();
        Entry[] entries = new Entry[size];
        for (int i = 0; i < size; i++) {
            entries[i] = readEntry(in);
        }
        return List.of(entries);
    }

    // ---- templates and selectors ----

    static void writeTemplate(ObjectDataOutput out, Template template) throws IOException {
        if (template instanceof Template.Any) {
            out.writeByte(ANY);
        } else if (template instanceof Template.OfType ofType) {
            out.writeByte(OF_TYPE);
            out.writeByte(ofType.type().ordinal());
        } else if (template instanceof Template.Value value) {
            out.writeByte(VALUE);
            writeEntry(out, value.value());
        } else {
            Template.TupleOf tuple = (Template.TupleOf) template;
            out.writeByte(TUPLE_OF);
            out.writeInt(tuple.arity());
            for (Template field : tuple.fields()) {
                writeTemplate(out, field);
            }
        }
    }

    static Template readTemplate(ObjectDataInput in) throws IOException {
        byte tag = in.readByte();
        return switch (tag) {
            case ANY -> Template.ANY;
            case OF_TYPE -> Template.type(EntryType.values()[in.readByte()]);
            case VALUE -> Template.value(readEntry(in));
            case TUPLE_OF -> {
                int arity = in.readInt();
                List<Template> fields = new ArrayList<>(arity);
                for (int i = 0; i < arity; i++) {
                    fields.add(readTemplate(in));
                }
                yield new Template.TupleOf(fields);
            }
            default -> throw new IOException("unknown template tag " + tag);
        };
    }

    static void writeSelectors(ObjectDataOutput out, Selector[] selectors) throws IOException {
        out.writeInt(selectors.length);
        for (Selector selector : selectors) {
            if (selector instanceof Selector.Ordered ordered) {
                out.writeByte(ORDERED);
                out.writeByte(ordered.order().ordinal());
            } else if (selector instanceof Selector.Key key) {
                out.writeByte(KEY);
                out.writeString(key.key());
            } else if (selector instanceof Selector.Vector vector) {
                out.writeByte(VECTOR);
                out.writeInt(vector.index());
            } else {
                out.writeByte(MATCHING);
                writeTemplate(out, ((Selector.Matching) selector).template());
            }
            out.writeInt(selector.count());
        }
    }

    static Selector[] readSelectors(ObjectDataInput in) throws IOException {
        Selector[] selectors = new Selector[in.readInt()];
        for (int i = 0; i < selectors.length; i++) {
            byte tag = in.readByte();
            selectors[i] = switch (tag) {
                case ORDERED -> {
                    Order order = Order.values()[in.readByte()];
                    yield Selector.order(order, in.readInt());
                }
                case KEY -> {
                    String key = in.readString();
                    yield Selector.key(key, in.readInt());
                }
                case VECTOR -> {
                    int index = in.readInt();
                    yield Selector.vector(index, in.readInt());
                }
                case MATCHING -> {
                    Template template = readTemplate(in);
                    yield Selector.template(template, in.readInt());
                }
                default -> throw new IOException("unknown selector tag " + tag);
            };
        }
        return selectors;
    }

    // ---- items, specs, placed entries ----

    static void writeItems(ObjectDataOutput out, List<Item> items) throws IOException {
        out.writeInt(items.size());
        for (Item item : items) {
            writeEntry(out, item.entry());
            out.writeString(item.key());
            out.writeInt(item.index());
        }
    }

    static List<Item> readItems(ObjectDataInput in) throws IOException {
        int size = in.readInt();
        List<Item> items = new ArrayList<>(size);
        for (int i = 0; i < size; i++) {
            Entry entry = readEntry(in);
            String key = in.readString();
            items.add(new Item(entry, key, in.readInt()));
        }
        return items;
    }

    static void writeSpec(ObjectDataOutput out, ContainerSpec spec) throws IOException {
        out.writeString(spec.name());
        out.writeInt(spec.capacity());
        out.writeByte(spec.uniqueness().ordinal());
        out.writeByte(spec.order().ordinal());
        out.writeBoolean(spec.keyView());
        out.writeBoolean(spec.vectorView());
    }

    static ContainerSpec readSpec(ObjectDataInput in) throws IOException {
        String name = in.readString();
        int capacity = in.readInt();
        Uniqueness uniqueness = Uniqueness.values()[in.readByte()];
        Order order = Order.values()[in.readByte()];
        boolean keyView = in.readBoolean();
        return new ContainerSpec(name, capacity, uniqueness, order, keyView, in.readBoolean());
    }

    static void writePlaced(ObjectDataOutput out, PlacedEntry placed) throws IOException {
        writeEntry(out, placed.entry());
        out.writeString(placed.key());
        out.writeInt(placed.position());
        out.writeLong(placed.written());
        out.writeLong(placed.used());
    }

    static PlacedEntry readPlaced(ObjectDataInput in) throws IOException {
        Entry entry = readEntry(in);
        String key = in.readString();
        int position = in.readInt();
        long written = in.readLong();
        return new PlacedEntry(entry, key, position, written, in.readLong());
    }

    static void writePlacedList(ObjectDataOutput out, List<PlacedEntry> placed) throws IOException {
        out.writeInt(placed.size());
        for (PlacedEntry entry : placed) {
            writePlaced(out, entry);
        }
    }

    static List<PlacedEntry> readPlacedList(ObjectDataInput in) throws IOException {
        int size = in.readInt();
        List<PlacedEntry> placed = new ArrayList<>(size);
        for (int i = 0; i < size; i++) {
            placed.add(readPlaced(in));
        }
        return placed;
    }

    // ---- small pieces ----

    static void writeOperations(ObjectDataOutput out, Set<Operation> operations) throws IOException {
        int bits = 0;
        for (Operation operation : operations) {
            bits |= 1 << operation.ordinal();
        }
        out.writeInt(bits);
    }

    static Set<Operation> readOperations(ObjectDataInput in) throws IOException {
        int bits = in.readInt();
        Set<Operation> operations = EnumSet.noneOf(Operation.class);
        for (Operation operation : Operation.values()) {
            if ((bits & (1 << operation.ordinal())) != 0) {
                operations.add(operation);
            }
        }
        return operations;
    }

    static void writeUuid(ObjectDataOutput out, UUID uuid) throws IOException {
        out.writeLong(uuid.getMostSignificantBits());
        out.writeLong(uuid.getLeastSignificantBits());
    }

    static UUID readUuid(ObjectDataInput in) throws IOException {
        long most = in.readLong();
        return new UUID(most, in.readLong());
    }

    static void writeUuids(ObjectDataOutput out, Set<UUID> uuids) throws IOException {
        out.writeInt(uuids.size());
        for (UUID uuid : uuids) {
            writeUuid(out, uuid);
        }
    }

    /** A set written by {@link #writeUuids}; the empty one is immutable. */
    static Set<UUID> readUuids(ObjectDataInput in) throws IOException {
        int count = in.readInt();
        if (count == 0) {
            return Set.of();
        }
        Set<UUID> uuids = new HashSet<>(count * 2);
        for (int i = 0; i < count; i++) {
            uuids.add(readUuid(in));
        }
        return uuids;
    }
}
