package robotworld.space.wire;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;

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
import robotworld.space.Uniqueness;

/** The JSON form of {@link WireReader}: Jackson's streaming parser over the message's bytes. */
final class JsonWireReader extends WireReader {

    private final JsonParser parser;
    private final WireLimits limits;
    private final CrefMapping crefs;
    /** The field names of the open objects, outermost first; {@link #objectStarts}: where each one's names begin. */
    private String[] names = new String[16];
    private int nameCount;
    private int[] objectStarts = new int[8];
    /** Per open object, the names beyond its first {@value #SCANNED_NAMES}, once it has that many (else null). */
    private Set<String>[] moreNames = newSets(8);
    private int openObjects;
    /** The name of the field just read. */
    private String field;

    private JsonWireReader(JsonParser parser, WireLimits limits, CrefMapping crefs) {
        this.parser = parser;
        this.limits = limits;
        this.crefs = crefs;
    }

    /** A reader over {@code length} bytes of {@code data} from {@code offset}. */
    static WireReader open(JsonFactory factory, WireLimits limits, CrefMapping crefs, byte[] data, int offset,
                           int length) {
        try {
            return new JsonWireReader(factory.createParser(data, offset, length), limits, crefs);
        } catch (IOException e) {
            throw new WireFormatException("cannot read the message: " + e.getMessage(), e);
        }
    }

    // ---- structure ----

    /** Expects the start of an object. */
    public void startObject() {
        expect(JsonToken.START_OBJECT, "an object");
    }

    /** The next field name of the current object, or null at its end. */
    public String nextField() {
        JsonToken token = next();
        if (token == JsonToken.END_OBJECT) {
            return null;
        }
        if (token != JsonToken.FIELD_NAME) {
            throw new WireFormatException("expected a field name or '}', found " + describe(token));
        }
        return field;
    }

    /** Expects that nothing follows the message's top-level value. */
    public void end() {
        JsonToken token = next();
        if (token != null) {
            throw new WireFormatException("unexpected content after the message: " + describe(token));
        }
    }

    /** Skips the value of the current field. */
    public void skipValue() {
        try {
            parser.nextToken();
            parser.skipChildren();
        } catch (IOException e) {
            throw malformed(e);
        }
    }

    // ---- scalars ----

    /** A 64-bit integer. */
    public long readLong(String what) {
        JsonToken token = next();
        return longValue(token, what);
    }

    /** A string of at most the string limit. */
    public String readString(String what) {
        JsonToken token = next();
        if (token != JsonToken.VALUE_STRING) {
            throw new WireFormatException(what + " must be a string, found " + describe(token));
        }
        return text();
    }

    /** A string, or null for JSON null. */
    public String readNullableString(String what) {
        JsonToken token = next();
        if (token == JsonToken.VALUE_NULL) {
            return null;
        }
        if (token != JsonToken.VALUE_STRING) {
            throw new WireFormatException(what + " must be a string or null, found " + describe(token));
        }
        return text();
    }

    /** true or false. */
    public boolean readBoolean(String what) {
        JsonToken token = next();
        if (token == JsonToken.VALUE_TRUE) {
            return true;
        }
        if (token == JsonToken.VALUE_FALSE) {
            return false;
        }
        throw new WireFormatException(what + " must be true or false, found " + describe(token));
    }

    /** A list of strings (at most {@code max}). */
    public List<String> readStrings(String what, int max) {
        expectArray(what);
        List<String> values = new ArrayList<>();
        JsonToken token;
        while ((token = next()) != JsonToken.END_ARRAY) {
            if (token != JsonToken.VALUE_STRING) {
                throw new WireFormatException(what + " must hold strings, found " + describe(token));
            }
            if (values.size() == max) {
                throw new WireFormatException(what + ": more than " + max + " values");
            }
            values.add(text());
        }
        return values;
    }

    // ---- entries ----

    /** One entry: integer, string, cref object or tuple array. */
    public Entry readEntry() {
        return entry(next(), 0);
    }

    /** An array of entries. */
    public List<Entry> readEntries(String what) {
        expectArray(what);
        List<Entry> entries = new ArrayList<>();
        JsonToken token;
        while ((token = next()) != JsonToken.END_ARRAY) {
            entries.add(entry(token, 0));
        }
        return entries;
    }

    private Entry entry(JsonToken token, int depth) {
        if (token == null) {
            throw new WireFormatException("the message ends inside an entry");
        }
        switch (token) {
            case VALUE_NUMBER_INT:
                return new IntEntry(longValue(token, "integer entry"));
            case VALUE_STRING:
                return new StringEntry(text());
            case START_ARRAY:
                if (depth + 1 > limits.maxDepth()) {
                    throw new WireFormatException("tuples nest deeper than " + limits.maxDepth());
                }
                List<Entry> fields = new ArrayList<>();
                JsonToken field;
                while ((field = next()) != JsonToken.END_ARRAY) {
                    fields.add(entry(field, depth + 1));
                }
                return new Tuple(fields);
            case START_OBJECT:
                return crefFields();
            default:
                throw new WireFormatException("an entry must be an integer, a string, a tuple array or a cref object;"
                        + " found " + describe(token));
        }
    }

    /** A cref object: {@code {"cref": id, "space": uri}}. */
    public ContainerRef readCref() {
        expect(JsonToken.START_OBJECT, "a cref object");
        return crefFields();
    }

    private ContainerRef crefFields() {
        String id = null;
        String space = null;
        String field;
        while ((field = nextField()) != null) {
            switch (field) {
                case "cref" -> id = readString("cref");
                case "space" -> space = readString("space");
                default -> throw unknownField(field);
            }
        }
        if (id == null || space == null) {
            throw new WireFormatException("a cref needs 'cref' (its id) and 'space' (its space's URI)");
        }
        return cref(crefs, id, space);
    }

    // ---- items, templates, selectors, specs ----

    /** An array of items: {@code {"entry": e, "key": k, "index": i}} with key and index optional. */
    public List<Item> readItems() {
        expectArray("items");
        List<Item> items = new ArrayList<>();
        JsonToken token;
        while ((token = next()) != JsonToken.END_ARRAY) {
            if (token != JsonToken.START_OBJECT) {
                throw new WireFormatException("each item must be an object, found " + describe(token));
            }
            if (items.size() == limits.maxItems()) {
                throw new WireFormatException("more than " + limits.maxItems() + " items in one request");
            }
            items.add(itemFields());
        }
        return items;
    }

    private Item itemFields() {
        Entry entry = null;
        String key = null;
        int index = Item.APPEND;
        String field;
        while ((field = nextField()) != null) {
            switch (field) {
                case "entry" -> entry = readEntry();
                case "key" -> key = readString("key");
                case "index" -> index = readInt("index", 0, Integer.MAX_VALUE);
                default -> throw unknownField(field);
            }
        }
        if (entry == null) {
            throw new WireFormatException("an item needs an 'entry'");
        }
        return new Item(entry, key, index);
    }

    /** A template object. */
    public Template readTemplate() {
        return template(next(), 0);
    }

    private Template template(JsonToken token, int depth) {
        if (token != JsonToken.START_OBJECT) {
            throw new WireFormatException("a template must be an object, found " + describe(token));
        }
        String kind = nextField();
        if (kind == null) {
            throw new WireFormatException("a template needs one of 'any', 'type', 'value', 'tuple'");
        }
        Template template;
        switch (kind) {
            case "any" -> {
                readBoolean("any");
                template = Template.ANY;
            }
            case "type" -> template = Template.type(Wire.entryType(readString("type")));
            case "value" -> template = Template.value(readEntry());
            case "tuple" -> {
                if (depth + 1 > limits.maxDepth()) {
                    throw new WireFormatException("tuple templates nest deeper than " + limits.maxDepth());
                }
                expectArray("tuple template");
                List<Template> fields = new ArrayList<>();
                JsonToken field;
                while ((field = next()) != JsonToken.END_ARRAY) {
                    fields.add(template(field, depth + 1));
                }
                template = new Template.TupleOf(fields);
            }
            default -> throw unknownField(kind);
        }
        if (nextField() != null) {
            throw new WireFormatException("a template object has exactly one field");
        }
        return template;
    }

    /** An array of selectors. */
    public Selector[] readSelectors() {
        expectArray("selectors");
        List<Selector> selectors = new ArrayList<>();
        JsonToken token;
        while ((token = next()) != JsonToken.END_ARRAY) {
            if (token != JsonToken.START_OBJECT) {
                throw new WireFormatException("each selector must be an object, found " + describe(token));
            }
            if (selectors.size() == limits.maxSelectors()) {
                throw new WireFormatException("more than " + limits.maxSelectors() + " selectors");
            }
            selectors.add(selectorFields());
        }
        return selectors.toArray(new Selector[0]);
    }

    private Selector selectorFields() {
        Order order = null;
        String key = null;
        Integer index = null;
        Template template = null;
        int count = 1;
        int kinds = 0;
        String field;
        while ((field = nextField()) != null) {
            switch (field) {
                case "order" -> {
                    order = Wire.order(readString("order"));
                    kinds++;
                }
                case "key" -> {
                    key = readString("key");
                    kinds++;
                }
                case "vector" -> {
                    index = readInt("vector", 0, Integer.MAX_VALUE);
                    kinds++;
                }
                case "template" -> {
                    template = readTemplate();
                    kinds++;
                }
                case "count" -> count = readCount();
                default -> throw unknownField(field);
            }
        }
        if (kinds != 1) {
            throw new WireFormatException("a selector has exactly one of 'order', 'key', 'vector', 'template'");
        }
        return selector(order, key, index, template, count);
    }

    private int readCount() {
        JsonToken token = next();
        if (token == JsonToken.VALUE_STRING && "all".equals(text())) {
            return Selector.ALL;
        }
        long count = longValue(token, "count");
        if (count < 1 || count > limits.maxCount()) {
            throw new WireFormatException("count must be \"all\" or in 1.." + limits.maxCount() + "; was " + count);
        }
        return (int) count;
    }

    /** A container spec object. */
    public ContainerSpec readSpec() {
        expect(JsonToken.START_OBJECT, "a spec object");
        ContainerSpec spec = ContainerSpec.defaults();
        String field;
        while ((field = nextField()) != null) {
            switch (field) {
                case "name" -> {
                    String name = readNullableString("name");
                    if (name != null && name.isBlank()) {
                        throw new WireFormatException("a container name must not be blank");
                    }
                    spec = name == null ? spec.anonymous() : spec.named(name);
                }
                case "capacity" -> {
                    JsonToken token = next();
                    if (token == JsonToken.VALUE_STRING && "unbounded".equals(text())) {
                        spec = spec.unbounded();
                    } else {
                        long capacity = longValue(token, "capacity");
                        if (capacity < 1 || capacity > Integer.MAX_VALUE) {
                            throw new WireFormatException("capacity must be \"unbounded\" or positive; was " + capacity);
                        }
                        spec = spec.bounded((int) capacity);
                    }
                }
                case "uniqueness" -> spec = Wire.uniqueness(readString("uniqueness")) == Uniqueness.SET
                        ? spec.set() : spec.bag();
                case "order" -> spec = spec.ordered(Wire.order(readString("order")));
                case "keyView" -> spec = readBoolean("keyView") ? spec.withKeyView()
                        : new ContainerSpec(spec.name(), spec.capacity(), spec.uniqueness(), spec.order(), false,
                        spec.vectorView());
                case "vectorView" -> spec = readBoolean("vectorView") ? spec.withVectorView()
                        : new ContainerSpec(spec.name(), spec.capacity(), spec.uniqueness(), spec.order(),
                        spec.keyView(), false);
                default -> throw unknownField(field);
            }
        }
        return spec;
    }

    /** An array of operation names. */
    public Set<Operation> readOperations() {
        Set<Operation> operations = EnumSet.noneOf(Operation.class);
        for (String name : readStrings("operations", Operation.values().length * 2)) {
            operations.add(Wire.operation(name));
        }
        return operations;
    }

    // ---- low level ----

    private JsonToken next() {
        JsonToken token = nextToken();
        if (token == JsonToken.START_OBJECT) {
            openObject();
        } else if (token == JsonToken.FIELD_NAME) {
            field = name();
            noteField(field);
        } else if (token == JsonToken.END_OBJECT) {
            openObjects--;
            nameCount = objectStarts[openObjects];
            moreNames[openObjects] = null;
        }
        return token;
    }

    // A message that names a field twice is refused, as its meaning would depend on which one a reader keeps. Checked
    // here rather than by the parser's own detection, which builds a hash set per object: messages have objects of a
    // few fields, and a scan of those is what costs least. An object with more (fields a reader skips, say) goes on
    // in a hash set, so that a message of many names cannot make the check quadratic.

    /** Names an object may have before they are kept in a hash set instead of scanned. */
    private static final int SCANNED_NAMES = 16;

    private void openObject() {
        if (openObjects == objectStarts.length) {
            objectStarts = Arrays.copyOf(objectStarts, openObjects * 2);
            moreNames = Arrays.copyOf(moreNames, openObjects * 2);
        }
        objectStarts[openObjects++] = nameCount;
    }

    private void noteField(String name) {
        int object = openObjects - 1;
        for (int i = objectStarts[object]; i < nameCount; i++) {
            if (names[i].equals(name)) {
                throw twice(name);
            }
        }
        if (nameCount - objectStarts[object] < SCANNED_NAMES) {
            if (nameCount == names.length) {
                names = Arrays.copyOf(names, nameCount * 2);
            }
            names[nameCount++] = name;
            return;
        }
        if (moreNames[object] == null) {
            moreNames[object] = new java.util.HashSet<>();
        }
        if (!moreNames[object].add(name)) {
            throw twice(name);
        }
    }

    private static WireFormatException twice(String name) {
        return new WireFormatException("the field '" + Wire.truncate(name) + "' appears twice in one object");
    }

    @SuppressWarnings("unchecked")
    private static Set<String>[] newSets(int size) {
        return (Set<String>[]) new Set<?>[size];
    }

    private JsonToken nextToken() {
        try {
            return parser.nextToken();
        } catch (StreamConstraintsException e) {
            throw new WireFormatException("limit exceeded: " + e.getOriginalMessage(), e);
        } catch (IOException e) {
            throw malformed(e);
        }
    }

    private String text() {
        try {
            return parser.getText();
        } catch (StreamConstraintsException e) {
            throw new WireFormatException("limit exceeded: " + e.getOriginalMessage(), e);
        } catch (IOException e) {
            throw malformed(e);
        }
    }

    private String name() {
        try {
            return parser.currentName();
        } catch (IOException e) {
            throw malformed(e);
        }
    }

    private long longValue(JsonToken token, String what) {
        if (token != JsonToken.VALUE_NUMBER_INT) {
            throw new WireFormatException(what + " must be an integer, found " + describe(token));
        }
        try {
            JsonParser.NumberType type = parser.getNumberType();
            if (type == JsonParser.NumberType.BIG_INTEGER) {
                throw new WireFormatException(what + " does not fit in 64 bits");
            }
            return parser.getLongValue();
        } catch (StreamConstraintsException e) {
            throw new WireFormatException("limit exceeded: " + e.getOriginalMessage(), e);
        } catch (IOException e) {
            throw malformed(e);
        }
    }

    private void expect(JsonToken expected, String what) {
        JsonToken token = next();
        if (token != expected) {
            throw new WireFormatException("expected " + what + ", found " + describe(token));
        }
    }

    private void expectArray(String what) {
        JsonToken token = next();
        if (token != JsonToken.START_ARRAY) {
            throw new WireFormatException(what + " must be an array, found " + describe(token));
        }
    }

    private static String describe(JsonToken token) {
        if (token == null) {
            return "the end of the message";
        }
        return switch (token) {
            case START_OBJECT -> "an object";
            case END_OBJECT -> "'}'";
            case START_ARRAY -> "an array";
            case END_ARRAY -> "']'";
            case FIELD_NAME -> "a field name";
            case VALUE_STRING -> "a string";
            case VALUE_NUMBER_INT -> "an integer";
            case VALUE_NUMBER_FLOAT -> "a fractional number";
            case VALUE_TRUE, VALUE_FALSE -> "a boolean";
            case VALUE_NULL -> "null";
            default -> token.toString();
        };
    }

    private static WireFormatException malformed(IOException e) {
        String message = e instanceof com.fasterxml.jackson.core.JsonProcessingException processing
                ? processing.getOriginalMessage() : e.getMessage();
        return new WireFormatException("malformed JSON: " + message, e);
    }

    @Override
    public void close() {
        try {
            parser.close();
        } catch (IOException ignored) {
            // reading from a byte array: nothing to release
        }
    }
}
