package robotworld.space.server;

import java.util.List;
import java.util.Set;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Item;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.wire.Wire;
import robotworld.space.wire.WireFormatException;
import robotworld.space.wire.WireReader;

/**
 * The fields of one request body, parsed in one pass; each operation then takes the ones it needs and fails
 * with a clear message when one is missing. Unknown fields are rejected.
 */
final class RequestFields {

    ContainerRef container;
    Timeout timeout;
    Selector[] selectors = new Selector[0];
    List<Item> items;
    ContainerSpec spec;
    String name;
    String call;
    /** The container the client says call {@link #call} ran on ({@code call: "id/container"}, to settle it), or null. */
    String callContainer;
    String session;
    String subscription;
    Set<Operation> operations;
    NotificationMode mode;
    List<String> calls;
    /** For each of {@link #calls}, the container its client says it ran on (null where it said none). */
    List<String> callContainers;
    /** The take of a {@code writeThenTake}: its container, selectors and call id. */
    RequestFields take;

    static RequestFields parse(WireReader in, int maxAcks) {
        RequestFields fields = parseObject(in, maxAcks, true);
        in.end();
        return fields;
    }

    private static RequestFields parseObject(WireReader in, int maxAcks, boolean top) {
        RequestFields fields = new RequestFields();
        in.startObject();
        String field;
        while ((field = in.nextField()) != null) {
            switch (field) {
                case "container" -> fields.container = in.readCref();
                case "timeout" -> fields.timeout = in.readTimeout();
                case "selectors" -> fields.selectors = in.readSelectors();
                case "items" -> fields.items = in.readItems();
                case "spec" -> fields.spec = in.readSpec();
                case "name" -> fields.name = in.readString("name");
                case "call" -> {
                    String[] reference = callReference(in.readString("call"), "call");
                    fields.call = reference[0];
                    fields.callContainer = reference[1];
                }
                case "session" -> fields.session = id(in.readString("session"), "session");
                case "subscription" -> fields.subscription = id(in.readString("subscription"), "subscription");
                case "operations" -> fields.operations = in.readOperations();
                case "mode" -> fields.mode = in.readMode();
                case "calls" -> {
                    List<String> references = in.readStrings("calls", maxAcks);
                    fields.calls = new java.util.ArrayList<>(references.size());
                    fields.callContainers = new java.util.ArrayList<>(references.size());
                    for (String text : references) {
                        String[] reference = callReference(text, "calls");
                        fields.calls.add(reference[0]);
                        fields.callContainers.add(reference[1]);
                    }
                }
                case "take" -> {
                    if (!top) {
                        throw in.unknownField(field); // one level only
                    }
                    fields.take = parseObject(in, maxAcks, false);
                }
                default -> throw in.unknownField(field);
            }
        }
        return fields;
    }

    /** Checks an id: 1..128 characters of letters, digits, '-', '_', '.', ':'. */
    /**
     * A call reference: a call id, or {@code id/containerId} when the client names the container the call ran on
     * (a clustered space then settles it there instead of asking every container).
     *
     * @return the id and the container id (null if none was named)
     */
    static String[] callReference(String value, String what) {
        int slash = value.indexOf('/');
        if (slash < 0) {
            return new String[] {id(value, what), null};
        }
        return new String[] {id(value.substring(0, slash), what), id(value.substring(slash + 1), what + " container")};
    }

    static String id(String value, String what) {
        if (value.isEmpty() || value.length() > Wire.MAX_ID_CHARS) {
            throw new WireFormatException(what + " id must have 1.." + Wire.MAX_ID_CHARS + " characters");
        }
        if (!Wire.isId(value)) {
            throw new WireFormatException(what + " id may hold only letters, digits, '-', '_', '.', ':'");
        }
        return value;
    }

    <T> T required(T value, String what) {
        if (value == null) {
            throw new WireFormatException("this request needs '" + what + "'");
        }
        return value;
    }
}
