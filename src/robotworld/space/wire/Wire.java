package robotworld.space.wire;

import java.util.Locale;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.util.JsonRecyclerPools;

import robotworld.space.EntryType;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Uniqueness;

/** Shared pieces of the wire format: the JSON factory with its limits, and the names of enum values. */
public final class Wire {

    /** The media type of every request and answer body. */
    public static final String MEDIA_TYPE = "application/json";
    /** The media type of the notification stream: one JSON object per line. */
    public static final String STREAM_MEDIA_TYPE = "application/x-ndjson";
    /** Header carrying acknowledgements of earlier takes, comma-separated call ids. */
    public static final String ACK_HEADER = "Space-Ack";

    private Wire() {
    }

    /** A JSON factory whose parsers enforce {@code limits} on nesting and string length. */
    public static JsonFactory factory(WireLimits limits) {
        // a tuple level costs one JSON level; a tuple template two ({"tuple":[...]}); plus the envelope
        StreamReadConstraints constraints = StreamReadConstraints.builder()
                .maxNestingDepth(2 * limits.maxDepth() + 8)
                .maxStringLength(limits.maxStringChars())
                .maxNumberLength(24)
                .maxNameLength(256)
                .maxDocumentLength(limits.maxBodyBytes() + 1L)
                .build();
        // a field named twice is refused by WireReader (more cheaply than the parser's own detection would)
        return JsonFactory.builder()
                .streamReadConstraints(constraints)
                .disable(JsonFactory.Feature.INTERN_FIELD_NAMES)
                // buffers shared through a pool, not one set per thread: the server writes an answer to a waiting
                // call while the answer of the call that satisfied it is open on the same thread, and with
                // per-thread buffers that second writer allocated 16 KB of fresh buffers each time; the lock-free
                // pool, as the two selector threads take and give back buffers all the time
                .recyclerPool(JsonRecyclerPools.newLockFreePool())
                .build()
                .disable(JsonParser.Feature.AUTO_CLOSE_SOURCE);
    }

    /** The longest id (call, session, subscription) the wire carries. */
    public static final int MAX_ID_CHARS = 128;

    /**
     * Whether {@code text} is a valid id on the wire: 1 to {@value #MAX_ID_CHARS} letters, digits, {@code - _ . :}
     * (so that ids travel in headers and call references unquoted).
     */
    public static boolean isId(String text) {
        if (text.isEmpty() || text.length() > MAX_ID_CHARS) {
            return false;
        }
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'
                    || c == '.' || c == ':')) {
                return false;
            }
        }
        return true;
    }

    /** The wire name of an enum value: lower case, underscores as dashes. */
    public static String name(Enum<?> value) {
        return value.name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    static <E extends Enum<E>> E value(Class<E> type, String name, String what) {
        for (E constant : type.getEnumConstants()) {
            if (name(constant).equals(name)) {
                return constant;
            }
        }
        throw new WireFormatException(what + ": unknown value '" + truncate(name) + "'");
    }

    /** A string cut to a length that is safe to echo in an error message. */
    static String truncate(String text) {
        return text.length() <= 40 ? text : text.substring(0, 40) + "...";
    }

    static EntryType entryType(String name) {
        return value(EntryType.class, name, "template type");
    }

    static Order order(String name) {
        return value(Order.class, name, "order");
    }

    static Uniqueness uniqueness(String name) {
        return value(Uniqueness.class, name, "uniqueness");
    }

    static Operation operation(String name) {
        return value(Operation.class, name, "operation");
    }

    static NotificationMode mode(String name) {
        return value(NotificationMode.class, name, "mode");
    }

    /** The end reason of a subscription, by wire name. */
    public static SubscriptionEnd subscriptionEnd(String name) {
        return value(SubscriptionEnd.class, name, "subscription end");
    }
}
