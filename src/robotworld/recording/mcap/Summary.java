package robotworld.recording.mcap;

import java.util.List;

/**
 * What a file's summary section says (or, for a file without one, what a full read found).
 *
 * @param schemas     every schema
 * @param channels    every channel
 * @param statistics  the counts and time range
 * @param chunks      one per chunk; empty when the file has no chunk index
 * @param attachments name, media type and size of each attachment
 * @param metadata    the names of the metadata records
 */
public record Summary(List<Schema> schemas, List<Channel> channels, Statistics statistics, List<ChunkInfo> chunks,
                      List<AttachmentInfo> attachments, List<String> metadata) {

    /** Copies the lists. */
    public Summary {
        schemas = List.copyOf(schemas);
        channels = List.copyOf(channels);
        chunks = List.copyOf(chunks);
        attachments = List.copyOf(attachments);
        metadata = List.copyOf(metadata);
    }

    /**
     * An attachment as the summary lists it.
     *
     * @param offset    where its record starts
     * @param name      its name
     * @param mediaType its media type
     * @param size      its size in bytes
     */
    public record AttachmentInfo(long offset, String name, String mediaType, long size) {
    }

    /** The channel with this id, or null. */
    public Channel channel(int id) {
        return channels.stream().filter(c -> c.id() == id).findFirst().orElse(null);
    }

    /** The schema with this id, or null. */
    public Schema schema(int id) {
        return schemas.stream().filter(s -> s.id() == id).findFirst().orElse(null);
    }
}
