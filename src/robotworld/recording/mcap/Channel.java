package robotworld.recording.mcap;

import java.util.Map;
import java.util.Objects;

/**
 * A channel record: one stream of messages on a topic.
 *
 * @param id              0..65535, unique in the file
 * @param schemaId        the schema of its messages, 0 for none
 * @param topic           e.g. {@code /CaterpillarRobot/Motor-Controller}
 * @param messageEncoding e.g. {@code json}
 * @param metadata        free key/value pairs
 */
public record Channel(int id, int schemaId, String topic, String messageEncoding, Map<String, String> metadata)
        implements DataRecord {

    /** Checks the fields; copies the metadata. */
    public Channel {
        if (id < 0 || id > 0xFFFF || schemaId < 0 || schemaId > 0xFFFF) {
            throw new IllegalArgumentException("channel and schema ids are 0..65535, were " + id + ", " + schemaId);
        }
        Objects.requireNonNull(topic, "topic");
        Objects.requireNonNull(messageEncoding, "messageEncoding");
        metadata = Map.copyOf(metadata);
    }
}
