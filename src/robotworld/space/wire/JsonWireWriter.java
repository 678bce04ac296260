package robotworld.space.wire;

import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.util.Collection;
import java.util.List;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.Item;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.StringEntry;
import robotworld.space.Template;
import robotworld.space.Tuple;

/** The JSON form of {@link WireWriter}: Jackson's streaming generator. */
final class JsonWireWriter extends WireWriter {

    private final JsonGenerator json;
    private final CrefMapping crefs;

    private JsonWireWriter(JsonGenerator json, CrefMapping crefs) {
        this.json = json;
        this.crefs = crefs;
    }

    /** A writer onto {@code out} (not closed by {@link #close()}). */
    static WireWriter open(JsonFactory factory, CrefMapping crefs, OutputStream out) {
        try {
            JsonGenerator generator = factory.createGenerator(out);
            generator.disable(JsonGenerator.Feature.AUTO_CLOSE_TARGET);
            return new JsonWireWriter(generator, crefs);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    // ---- structure ----

    /** Starts an object. */
    public WireWriter startObject() {
        return io(() -> json.writeStartObject());
    }

    /** Ends the current object. */
    public WireWriter endObject() {
        return io(() -> json.writeEndObject());
    }

    /** Writes a field name; its value follows (e.g. {@link #entry}). */
    public WireWriter field(String name) {
        return io(() -> json.writeFieldName(name));
    }

    /** Writes a string field (null as JSON null). */
    public WireWriter field(String name, String value) {
        return io(() -> {
            json.writeFieldName(name);
            if (value == null) {
                json.writeNull();
            } else {
                json.writeString(value);
            }
        });
    }

    /** Writes an integer field. */
    public WireWriter field(String name, long value) {
        return io(() -> json.writeNumberField(name, value));
    }

    /** Writes a boolean field. */
    public WireWriter field(String name, boolean value) {
        return io(() -> json.writeBooleanField(name, value));
    }

    /** Writes an array of strings. */
    public WireWriter strings(String name, Collection<String> values) {
        return io(() -> {
            json.writeArrayFieldStart(name);
            for (String value : values) {
                json.writeString(value);
            }
            json.writeEndArray();
        });
    }

    // ---- space values ----

    /** Writes one entry as a value (integer, string, tuple array or cref object). */
    public WireWriter entry(Entry entry) {
        return io(() -> writeEntry(entry));
    }

    /** Writes an array of entries as a field. */
    public WireWriter entries(String name, List<Entry> entries) {
        return io(() -> {
            json.writeArrayFieldStart(name);
            for (Entry entry : entries) {
                writeEntry(entry);
            }
            json.writeEndArray();
        });
    }

    private void writeEntry(Entry entry) throws IOException {
        if (entry instanceof IntEntry integer) {
            json.writeNumber(integer.value());
        } else if (entry instanceof StringEntry string) {
            json.writeString(string.value());
        } else if (entry instanceof Tuple tuple) {
            json.writeStartArray();
            for (Entry field : tuple.fields()) {
                writeEntry(field);
            }
            json.writeEndArray();
        } else {
            writeCref((ContainerRef) entry);
        }
    }

    /** Writes a cref field, translated to its wire form. */
    public WireWriter cref(String name, ContainerRef ref) {
        return io(() -> {
            json.writeFieldName(name);
            writeCref(ref);
        });
    }

    private void writeCref(ContainerRef ref) throws IOException {
        ContainerRef sent = crefs.outgoing(ref);
        json.writeStartObject();
        json.writeStringField("cref", sent.id());
        json.writeStringField("space", sent.space().toString());
        json.writeEndObject();
    }

    /** Writes the {@code items} field of a write or shift. */
    public WireWriter items(List<Item> items) {
        return io(() -> {
            json.writeArrayFieldStart("items");
            for (Item item : items) {
                json.writeStartObject();
                json.writeFieldName("entry");
                writeEntry(item.entry());
                if (item.key() != null) {
                    json.writeStringField("key", item.key());
                }
                if (item.hasIndex()) {
                    json.writeNumberField("index", item.index());
                }
                json.writeEndObject();
            }
            json.writeEndArray();
        });
    }

    /** Writes the {@code selectors} field of a read, take or destroy. */
    public WireWriter selectors(Selector[] selectors) {
        return io(() -> {
            json.writeArrayFieldStart("selectors");
            for (Selector selector : selectors) {
                writeSelector(selector);
            }
            json.writeEndArray();
        });
    }

    private void writeSelector(Selector selector) throws IOException {
        json.writeStartObject();
        if (selector instanceof Selector.Ordered ordered) {
            json.writeStringField("order", Wire.name(ordered.order()));
        } else if (selector instanceof Selector.Key byKey) {
            json.writeStringField("key", byKey.key());
        } else if (selector instanceof Selector.Vector byPosition) {
            json.writeNumberField("vector", byPosition.index());
        } else {
            json.writeFieldName("template");
            writeTemplate(((Selector.Matching) selector).template());
        }
        if (selector.count() == Selector.ALL) {
            json.writeStringField("count", "all");
        } else if (selector.count() != 1) {
            json.writeNumberField("count", selector.count());
        }
        json.writeEndObject();
    }

    private void writeTemplate(Template template) throws IOException {
        json.writeStartObject();
        if (template instanceof Template.Any) {
            json.writeBooleanField("any", true);
        } else if (template instanceof Template.OfType type) {
            json.writeStringField("type", Wire.name(type.type()));
        } else if (template instanceof Template.Value value) {
            json.writeFieldName("value");
            writeEntry(value.value());
        } else {
            json.writeArrayFieldStart("tuple");
            for (Template field : ((Template.TupleOf) template).fields()) {
                writeTemplate(field);
            }
            json.writeEndArray();
        }
        json.writeEndObject();
    }

    /** Writes a container spec field. */
    public WireWriter spec(String name, ContainerSpec spec) {
        return io(() -> {
            json.writeObjectFieldStart(name);
            if (spec.name() != null) {
                json.writeStringField("name", spec.name());
            }
            if (spec.isBounded()) {
                json.writeNumberField("capacity", spec.capacity());
            } else {
                json.writeStringField("capacity", "unbounded");
            }
            json.writeStringField("uniqueness", Wire.name(spec.uniqueness()));
            json.writeStringField("order", Wire.name(spec.order()));
            json.writeBooleanField("keyView", spec.keyView());
            json.writeBooleanField("vectorView", spec.vectorView());
            json.writeEndObject();
        });
    }

    /** Writes the {@code operations} field of a subscription. */
    public WireWriter operations(Collection<Operation> operations) {
        return io(() -> {
            json.writeArrayFieldStart("operations");
            for (Operation operation : operations) {
                json.writeString(Wire.name(operation));
            }
            json.writeEndArray();
        });
    }

    // ---- output ----

    /** Pushes what was generated to the output stream. */
    public void flush() {
        io(json::flush);
    }

    @Override
    public void close() {
        io(json::close);
    }

    private WireWriter io(IoAction action) {
        try {
            action.run();
            return this;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @FunctionalInterface
    private interface IoAction {
        void run() throws IOException;
    }
}
