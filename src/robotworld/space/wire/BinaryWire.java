package robotworld.space.wire;

import java.util.List;

/**
 * The compact binary form of the hot operations' bodies ({@code read}, {@code take}, {@code destroy}, {@code write},
 * {@code shift}, {@code writeThenTake}, {@code shiftThenTake} and their answers), beside JSON: the same fields and
 * values, without field names in text, quotes or number formatting, so that neither side runs a JSON parser or
 * generator for them. A message in this form starts with {@link #MARKER}, a byte no JSON text starts with, so the
 * two are told apart by their first byte. A server that reads it says {@code "binary": 1} in its description; it
 * answers a request in this form in this form (errors stay JSON), and clients send it only on framed connections.
 *
 * <pre>
 * message  = MARKER object
 * object   = { fieldCode:u8 value } 0x00           (each field at most once)
 * uvarint  = LEB128, at most 10 bytes;  long = zigzag(uvarint)
 * string   = uvarint(byte length) UTF-8 bytes
 * cref     = string(id) string(space URI)
 * entry    = 1 long | 2 string | 3 uvarint(n) entry*n (a tuple) | 4 cref
 * item     = entry flags:u8 [string key if flags&amp;1] [uvarint index if flags&amp;2]
 * template = 1 (any) | 2 type:u8 (1 integer, 2 string, 3 cref, 4 tuple) | 3 entry | 4 uvarint(n) template*n
 * selector = kind:u8 (1 order:u8 (0 random, 1 fifo, 2 lifo, 3 lru) | 2 string(key) | 3 uvarint(position)
 *            | 4 template) uvarint(count; 0 = all)
 * </pre>
 *
 * Field codes and value types are those of {@link #FIELDS}, in order from 1; limits are those of JSON
 * ({@link WireLimits}).
 */
public final class BinaryWire {

    /** The first byte of a message in the binary form. */
    public static final byte MARKER = (byte) 0xB1;
    /** The version a server names in its description ({@code "binary": 1}). */
    public static final int VERSION = 1;

    /** What a field's value is. */
    enum Kind { CREF, LONG, SELECTORS, ITEMS, STRING, OBJECT, ENTRIES, BOOLEAN }

    /** A field of the binary form: its name (as in JSON) and its value's kind. */
    record Field(String name, Kind kind) {
    }

    /** The fields, by code (index + 1). New fields are only ever appended. */
    static final List<Field> FIELDS = List.of(
            new Field("container", Kind.CREF),
            new Field("timeout", Kind.LONG),
            new Field("selectors", Kind.SELECTORS),
            new Field("items", Kind.ITEMS),
            new Field("call", Kind.STRING),
            new Field("take", Kind.OBJECT),
            new Field("entries", Kind.ENTRIES),
            new Field("displaced", Kind.ENTRIES),
            new Field("more", Kind.BOOLEAN),
            new Field("ack", Kind.BOOLEAN),
            new Field("written", Kind.BOOLEAN),
            new Field("count", Kind.LONG));

    static final int ENTRY_LONG = 1;
    static final int ENTRY_STRING = 2;
    static final int ENTRY_TUPLE = 3;
    static final int ENTRY_CREF = 4;
    static final int TEMPLATE_ANY = 1;
    static final int TEMPLATE_TYPE = 2;
    static final int TEMPLATE_VALUE = 3;
    static final int TEMPLATE_TUPLE = 4;
    static final int SELECTOR_ORDER = 1;
    static final int SELECTOR_KEY = 2;
    static final int SELECTOR_VECTOR = 3;
    static final int SELECTOR_TEMPLATE = 4;
    static final int ITEM_KEY = 1;
    static final int ITEM_INDEX = 2;

    /** The operations whose requests (and answers) may be in the binary form. */
    public static final java.util.Set<String> OPERATIONS = java.util.Set.of("read", "take", "destroy", "write",
            "shift", "writeThenTake", "shiftThenTake");

    private BinaryWire() {
    }

    /** The codes by field name, built once from {@link #FIELDS}: a writer looks one up per field. */
    private static final java.util.Map<String, Integer> CODES = codes();

    private static java.util.Map<String, Integer> codes() {
        java.util.Map<String, Integer> codes = new java.util.HashMap<>();
        for (int i = 0; i < FIELDS.size(); i++) {
            codes.put(FIELDS.get(i).name(), i + 1);
        }
        return java.util.Map.copyOf(codes);
    }

    /** The code of field {@code name}, or 0 if the binary form has no such field. */
    static int code(String name) {
        return CODES.getOrDefault(name, 0);
    }
}
