package robotworld.recording.mcap;

import java.util.Objects;

/**
 * An attachment record: a file kept beside the messages (e.g. the world's description).
 *
 * @param logTime    when it was recorded, ns since the epoch
 * @param createTime when it was made, ns since the epoch, 0 when unknown
 * @param name       e.g. {@code world.xml}
 * @param mediaType  e.g. {@code application/xml}
 * @param data       its content
 */
public record Attachment(long logTime, long createTime, String name, String mediaType, byte[] data)
        implements DataRecord {

    /** Checks the fields. */
    public Attachment {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(mediaType, "mediaType");
        Objects.requireNonNull(data, "data");
    }
}
