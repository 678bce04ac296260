package robotworld.space.remote;

import java.util.List;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireReader;

/**
 * The fields of one answer body, parsed in one pass. Unknown fields are skipped, so a newer server can add
 * fields without breaking older clients.
 */
final class Answer {

    static final Answer EMPTY = new Answer();

    List<Entry> entries = List.of();
    List<Entry> displaced = List.of();
    ContainerRef container;
    ContainerSpec spec;
    long count;
    long size;
    long blocked;
    long subscriptions;
    long sequence = -1;
    boolean more;
    boolean ack;
    /** writeThenTake: the write happened (also with "more" or an error of the take). */
    boolean written;
    String outcome;
    String subscription;
    String error;
    String message;
    String space;
    long maxWait = -1;
    /** The frame version the server speaks besides HTTP (0: none). */
    long frames;
    /** The version of the binary form of bodies the server reads in frames (0: none). */
    long binary;

    static Answer parse(WireContext wire, byte[] body) {
        Answer answer = new Answer();
        try (WireReader in = wire.reader(body, 0, body.length)) {
            in.startObject();
            String field;
            while ((field = in.nextField()) != null) {
                switch (field) {
                    case "entries" -> answer.entries = in.readEntries("entries");
                    case "displaced" -> answer.displaced = in.readEntries("displaced");
                    case "container" -> answer.container = in.readCref();
                    case "spec" -> answer.spec = in.readSpec();
                    case "count" -> answer.count = in.readLong("count");
                    case "size" -> answer.size = in.readLong("size");
                    case "blocked" -> answer.blocked = in.readLong("blocked");
                    case "subscriptions" -> answer.subscriptions = in.readLong("subscriptions");
                    case "sequence" -> answer.sequence = in.readLong("sequence");
                    case "more" -> answer.more = in.readBoolean("more");
                    case "ack" -> answer.ack = in.readBoolean("ack");
                    case "written" -> answer.written = in.readBoolean("written");
                    case "outcome" -> answer.outcome = in.readString("outcome");
                    case "subscription" -> answer.subscription = in.readString("subscription");
                    case "error" -> answer.error = in.readString("error");
                    case "message" -> answer.message = in.readString("message");
                    case "space" -> answer.space = in.readString("space");
                    case "maxWait" -> answer.maxWait = in.readLong("maxWait");
                    case "frames" -> answer.frames = in.readLong("frames");
                    case "binary" -> answer.binary = in.readLong("binary");
                    default -> in.skipValue();
                }
            }
        }
        return answer;
    }
}
