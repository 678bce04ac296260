/**
 * MCAP files: a small writer and reader of the MCAP container format (version 0, as published by its authors at
 * mcap.dev), written here because no maintained Java library exists. The recorder writes with it, the replayer
 * and {@code rwe record --info} read with it; files it writes are checked against the reference Python reader.
 *
 * <h2>The contract</h2>
 * <ul>
 *   <li>{@link robotworld.recording.mcap.McapWriter} writes in one pass, never seeking: header, then chunks of
 *       schema, channel and message records (uncompressed, each with its CRC32), each chunk followed by one
 *       message index per channel in it; on {@link robotworld.recording.mcap.McapWriter#close()} the data end
 *       record (with the data section's CRC32), the summary section (schemas, channels, statistics, chunk,
 *       attachment and metadata indexes, grouped by opcode), summary offsets and the footer (with the summary's
 *       CRC32). A file is valid and fully indexed once closed; before that, what was flushed is readable by a
 *       linear scan ({@link robotworld.recording.mcap.McapReader} reports it as unfinished).</li>
 *   <li>{@link robotworld.recording.mcap.McapReader} reads any MCAP file whose chunks are uncompressed or
 *       compressed with zstd or lz4 (the compressions the specification names), with or without summary, chunks
 *       or indexes; records it does not know (newer or private opcodes) are skipped, as the format asks. Another
 *       compression or a malformed file is an {@link robotworld.recording.mcap.McapFormatException} naming the
 *       byte offset, never a wrong result.</li>
 *   <li>Timestamps are nanoseconds since the Unix epoch. Strings are UTF-8.</li>
 * </ul>
 */
package robotworld.recording.mcap;
