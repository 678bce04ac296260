package robotworld.recording.mcap;

import java.util.Map;

/**
 * The statistics record of a file's summary.
 *
 * @param messageCount         messages in the file
 * @param schemaCount          distinct schema ids
 * @param channelCount         distinct channel ids
 * @param attachmentCount      attachments
 * @param metadataCount        metadata records
 * @param chunkCount           chunks
 * @param messageStartTime     earliest log time, 0 without messages
 * @param messageEndTime       latest log time, 0 without messages
 * @param channelMessageCounts messages per channel id
 */
public record Statistics(long messageCount, int schemaCount, long channelCount, long attachmentCount,
                         long metadataCount, long chunkCount, long messageStartTime, long messageEndTime,
                         Map<Integer, Long> channelMessageCounts) {

    /** Copies the map. */
    public Statistics {
        channelMessageCounts = Map.copyOf(channelMessageCounts);
    }
}
