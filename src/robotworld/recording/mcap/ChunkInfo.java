package robotworld.recording.mcap;

import java.util.Map;

/**
 * A chunk index record of a file's summary: where a chunk is and what it holds.
 *
 * @param messageStartTime    earliest log time in the chunk
 * @param messageEndTime      latest log time in the chunk
 * @param chunkStartOffset    where the chunk record starts in the file
 * @param chunkLength         the chunk record's length, opcode and length prefix included
 * @param messageIndexOffsets per channel id, where its message index record after the chunk starts
 * @param messageIndexLength  the length of all message index records after the chunk
 * @param compression         the chunk's compression, empty for none
 * @param compressedSize      the size of the chunk's records as stored
 * @param uncompressedSize    the size of the chunk's records
 */
public record ChunkInfo(long messageStartTime, long messageEndTime, long chunkStartOffset, long chunkLength,
                        Map<Integer, Long> messageIndexOffsets, long messageIndexLength, String compression,
                        long compressedSize, long uncompressedSize) {

    /** Copies the map. */
    public ChunkInfo {
        messageIndexOffsets = Map.copyOf(messageIndexOffsets);
    }
}
