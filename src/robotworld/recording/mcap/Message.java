package robotworld.recording.mcap;

import java.nio.charset.StandardCharsets;
import java.util.Objects;

/**
 * A message record.
 *
 * @param channelId   the channel it was published on
 * @param sequence    the publisher's counter (0 when it has none)
 * @param logTime     when it was recorded, ns since the epoch
 * @param publishTime when it was published, ns since the epoch
 * @param data        the message, in the channel's encoding
 */
public record Message(int channelId, long sequence, long logTime, long publishTime, byte[] data)
        implements DataRecord {

    /** Checks the fields. */
    public Message {
        if (channelId < 0 || channelId > 0xFFFF) {
            throw new IllegalArgumentException("a channel id is 0..65535, was " + channelId);
        }
        if (sequence < 0 || sequence > 0xFFFF_FFFFL) {
            throw new IllegalArgumentException("a sequence number is a uint32, was " + sequence);
        }
        Objects.requireNonNull(data, "data");
    }

    /** The message as text (JSON messages are UTF-8 text). */
    public String text() {
        return new String(data, StandardCharsets.UTF_8);
    }
}
