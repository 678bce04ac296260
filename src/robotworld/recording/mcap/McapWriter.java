package robotworld.recording.mcap;

import java.io.BufferedOutputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.zip.CRC32;

/**
 * Writes an MCAP file in one pass (see the package documentation for the layout). Not thread-safe: one thread
 * writes. Messages go into the current chunk; a chunk is written out when it reaches the chunk size or on
 * {@link #flush()}, and is readable from then on even if the program dies before {@link #close()}.
 *
 * <pre>{@code
 * try (McapWriter mcap = McapWriter.create(file, McapWriter.Options.defaults())) {
 *     int schema = mcap.addSchema("rwe.Liveness", "jsonschema", schemaBytes);
 *     int channel = mcap.addChannel("/rwe/liveness", "json", schema, Map.of());
 *     mcap.addMessage(channel, 1, nanos, nanos, json);
 * }
 * }</pre>
 */
public final class McapWriter implements Closeable {

    /**
     * How the file is written.
     *
     * @param profile   the header's profile, empty for none
     * @param library   the header's library, naming the writer
     * @param chunkSize a chunk is written out once its records reach this many bytes
     */
    public record Options(String profile, String library, int chunkSize) {

        /** Checks the values. */
        public Options {
            Objects.requireNonNull(profile, "profile");
            Objects.requireNonNull(library, "library");
            if (chunkSize < 1) {
                throw new IllegalArgumentException("the chunk size must be positive, was " + chunkSize);
            }
        }

        /** No profile, library "RobotWorldExplorer", chunks of 512 KiB. */
        public static Options defaults() {
            return new Options("", "RobotWorldExplorer", 512 * 1024);
        }

        /** With another library string. */
        public Options library(String newLibrary) {
            return new Options(profile, newLibrary, chunkSize);
        }

        /** With another chunk size. */
        public Options chunkSize(int bytes) {
            return new Options(profile, library, bytes);
        }
    }

    private final CountingOutput out;
    private final Options options;
    private final RecordBuffer chunk;
    private final RecordBuffer scratch = new RecordBuffer(256);
    private final Map<Integer, List<long[]>> chunkIndex = new LinkedHashMap<>();
    private long chunkStart;
    private long chunkEnd;
    private int chunkMessages;

    private final List<Schema> schemas = new ArrayList<>();
    private final List<Channel> channels = new ArrayList<>();
    private final Map<Integer, Channel> channelsById = new HashMap<>();
    private final Map<Integer, Long> channelCounts = new TreeMap<>();
    private final List<ChunkInfo> chunkInfos = new ArrayList<>();
    private final List<long[]> attachmentIndex = new ArrayList<>();
    private final List<Attachment> attachments = new ArrayList<>();
    private final List<Object[]> metadataIndex = new ArrayList<>();
    private long messageCount;
    private long startTime = -1;
    private long endTime;
    private boolean closed;

    /** Creates (or replaces) {@code file} and writes the magic and header. */
    public static McapWriter create(Path file, Options options) throws IOException {
        OutputStream stream = Files.newOutputStream(file);
        try {
            return new McapWriter(stream, options);
        } catch (IOException | RuntimeException e) {
            stream.close();
            throw e;
        }
    }

    /** Writes the magic and header to {@code stream}, which {@link #close()} closes. */
    public McapWriter(OutputStream stream, Options options) throws IOException {
        this.options = Objects.requireNonNull(options, "options");
        this.out = new CountingOutput(new BufferedOutputStream(stream, 64 * 1024));
        this.chunk = new RecordBuffer(Math.min(options.chunkSize(), 1 << 20) + 1024);
        out.write(Opcode.MAGIC);
        scratch.clear();
        int header = scratch.startRecord(Opcode.HEADER);
        scratch.string(options.profile()).string(options.library());
        scratch.endRecord(header);
        out.write(scratch);
    }

    /** Adds a schema; returns its id (1, 2, ...). Its record goes into the current chunk and the summary. */
    public int addSchema(String name, String encoding, byte[] data) throws IOException {
        ensureOpen();
        Schema schema = new Schema(schemas.size() + 1, name, encoding, data.clone());
        schemas.add(schema);
        writeSchema(chunk, schema);
        maybeWriteChunk();
        return schema.id();
    }

    /** Adds a channel; returns its id (0, 1, ...). Its record goes into the current chunk and the summary. */
    public int addChannel(String topic, String messageEncoding, int schemaId, Map<String, String> metadata)
            throws IOException {
        ensureOpen();
        if (schemaId != 0 && (schemaId > schemas.size())) {
            throw new IllegalArgumentException("no schema " + schemaId + " was added");
        }
        Channel channel = new Channel(channels.size(), schemaId, topic, messageEncoding, metadata);
        channels.add(channel);
        channelsById.put(channel.id(), channel);
        writeChannel(chunk, channel);
        maybeWriteChunk();
        return channel.id();
    }

    /** Adds a message on a channel added before. */
    public void addMessage(int channelId, long sequence, long logTime, long publishTime, byte[] data)
            throws IOException {
        ensureOpen();
        if (!channelsById.containsKey(channelId)) {
            throw new IllegalArgumentException("no channel " + channelId + " was added");
        }
        if (sequence < 0 || sequence > 0xFFFF_FFFFL) {
            throw new IllegalArgumentException("a sequence number is a uint32, was " + sequence);
        }
        int offset = chunk.size();
        int record = chunk.startRecord(Opcode.MESSAGE);
        chunk.u16(channelId).u32(sequence).u64(logTime).u64(publishTime).raw(data);
        chunk.endRecord(record);
        chunkIndex.computeIfAbsent(channelId, id -> new ArrayList<>()).add(new long[] {logTime, offset});
        chunkStart = chunkMessages == 0 ? logTime : Math.min(chunkStart, logTime);
        chunkEnd = chunkMessages == 0 ? logTime : Math.max(chunkEnd, logTime);
        chunkMessages++;
        messageCount++;
        channelCounts.merge(channelId, 1L, Long::sum);
        startTime = startTime < 0 ? logTime : Math.min(startTime, logTime);
        endTime = Math.max(endTime, logTime);
        maybeWriteChunk();
    }

    /** Adds an attachment (outside any chunk: the current chunk is written out first). */
    public void addAttachment(Attachment attachment) throws IOException {
        ensureOpen();
        writeChunk();
        long offset = out.count();
        scratch.clear();
        int record = scratch.startRecord(Opcode.ATTACHMENT);
        scratch.u64(attachment.logTime()).u64(attachment.createTime()).string(attachment.name())
                .string(attachment.mediaType()).u64(attachment.data().length).raw(attachment.data());
        CRC32 crc = new CRC32();
        crc.update(scratch.array(), 9, scratch.size() - 9);
        scratch.u32(crc.getValue());
        scratch.endRecord(record);
        out.write(scratch);
        attachmentIndex.add(new long[] {offset, scratch.size()});
        attachments.add(attachment);
    }

    /** Adds a metadata record (outside any chunk: the current chunk is written out first). */
    public void addMetadata(Metadata metadata) throws IOException {
        ensureOpen();
        writeChunk();
        long offset = out.count();
        scratch.clear();
        int record = scratch.startRecord(Opcode.METADATA);
        scratch.string(metadata.name()).stringMap(metadata.values());
        scratch.endRecord(record);
        out.write(scratch);
        metadataIndex.add(new Object[] {offset, (long) scratch.size(), metadata.name()});
    }

    /** Writes out the current chunk, if it holds anything, and pushes all bytes to the file. */
    public void flush() throws IOException {
        ensureOpen();
        writeChunk();
        out.flush();
    }

    /** Messages added so far. */
    public long messageCount() {
        return messageCount;
    }

    /** Bytes written to the file so far (the current chunk not included). */
    public long bytesWritten() {
        return out.count();
    }

    /** Bytes waiting in the current chunk. */
    public long bytesPending() {
        return chunk.size();
    }

    /**
     * Finishes the file: the last chunk, data end, summary, summary offsets, footer and magic; then closes the
     * stream. Idempotent.
     */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        try {
            writeChunk();
            scratch.clear();
            int dataEnd = scratch.startRecord(Opcode.DATA_END);
            scratch.u32(out.crc());
            scratch.endRecord(dataEnd);
            out.write(scratch);
            writeSummary();
            out.flush();
        } finally {
            closed = true;
            out.close();
        }
    }

    private void writeSummary() throws IOException {
        long summaryStart = out.count();
        RecordBuffer summary = new RecordBuffer(4096);
        List<long[]> groups = new ArrayList<>();
        int start = summary.size();
        for (Schema schema : schemas) {
            writeSchema(summary, schema);
        }
        group(groups, Opcode.SCHEMA, summaryStart, start, summary.size());
        start = summary.size();
        for (Channel channel : channels) {
            writeChannel(summary, channel);
        }
        group(groups, Opcode.CHANNEL, summaryStart, start, summary.size());
        start = summary.size();
        int statistics = summary.startRecord(Opcode.STATISTICS);
        summary.u64(messageCount).u16(schemas.size()).u32(channels.size()).u32(attachments.size())
                .u32(metadataIndex.size()).u32(chunkInfos.size()).u64(startTime < 0 ? 0 : startTime)
                .u64(startTime < 0 ? 0 : endTime).u16u64Map(channelCounts);
        summary.endRecord(statistics);
        group(groups, Opcode.STATISTICS, summaryStart, start, summary.size());
        start = summary.size();
        for (ChunkInfo info : chunkInfos) {
            int record = summary.startRecord(Opcode.CHUNK_INDEX);
            summary.u64(info.messageStartTime()).u64(info.messageEndTime()).u64(info.chunkStartOffset())
                    .u64(info.chunkLength()).u16u64Map(info.messageIndexOffsets()).u64(info.messageIndexLength())
                    .string(info.compression()).u64(info.compressedSize()).u64(info.uncompressedSize());
            summary.endRecord(record);
        }
        group(groups, Opcode.CHUNK_INDEX, summaryStart, start, summary.size());
        start = summary.size();
        for (int i = 0; i < attachments.size(); i++) {
            Attachment attachment = attachments.get(i);
            long[] where = attachmentIndex.get(i);
            int record = summary.startRecord(Opcode.ATTACHMENT_INDEX);
            summary.u64(where[0]).u64(where[1]).u64(attachment.logTime()).u64(attachment.createTime())
                    .u64(attachment.data().length).string(attachment.name()).string(attachment.mediaType());
            summary.endRecord(record);
        }
        group(groups, Opcode.ATTACHMENT_INDEX, summaryStart, start, summary.size());
        start = summary.size();
        for (Object[] metadata : metadataIndex) {
            int record = summary.startRecord(Opcode.METADATA_INDEX);
            summary.u64((Long) metadata[0]).u64((Long) metadata[1]).string((String) metadata[2]);
            summary.endRecord(record);
        }
        group(groups, Opcode.METADATA_INDEX, summaryStart, start, summary.size());
        long summaryOffsetStart = summaryStart + summary.size();
        for (long[] group : groups) {
            int record = summary.startRecord(Opcode.SUMMARY_OFFSET);
            summary.u8((int) group[0]).u64(group[1]).u64(group[2]);
            summary.endRecord(record);
        }
        summary.u8(Opcode.FOOTER).u64(20).u64(summaryStart).u64(summaryOffsetStart);
        CRC32 crc = new CRC32();
        crc.update(summary.array(), 0, summary.size());
        summary.u32(crc.getValue());
        summary.raw(Opcode.MAGIC);
        out.write(summary);
    }

    private static void group(List<long[]> groups, int opcode, long summaryStart, int from, int to) {
        if (to > from) {
            groups.add(new long[] {opcode, summaryStart + from, to - from});
        }
    }

    private void maybeWriteChunk() throws IOException {
        if (chunk.size() >= options.chunkSize()) {
            writeChunk();
        }
    }

    /** Writes the current chunk and its message indexes, if it holds any record. */
    private void writeChunk() throws IOException {
        if (chunk.size() == 0) {
            return;
        }
        long chunkOffset = out.count();
        CRC32 crc = new CRC32();
        crc.update(chunk.array(), 0, chunk.size());
        long start = chunkMessages == 0 ? 0 : chunkStart;
        long end = chunkMessages == 0 ? 0 : chunkEnd;
        scratch.clear();
        scratch.u8(Opcode.CHUNK);
        int lengthAt = scratch.size();
        scratch.u64(0);
        scratch.u64(start).u64(end).u64(chunk.size()).u32(crc.getValue()).string("").u64(chunk.size());
        long chunkLength = scratch.size() + (long) chunk.size();
        scratch.patchU64(lengthAt, chunkLength - 9);
        out.write(scratch);
        out.write(chunk.array(), 0, chunk.size());
        Map<Integer, Long> indexOffsets = new TreeMap<>();
        long indexStart = out.count();
        for (Map.Entry<Integer, List<long[]>> channel : chunkIndex.entrySet()) {
            indexOffsets.put(channel.getKey(), out.count());
            scratch.clear();
            int record = scratch.startRecord(Opcode.MESSAGE_INDEX);
            scratch.u16(channel.getKey()).u32(channel.getValue().size() * 16L);
            for (long[] entry : channel.getValue()) {
                scratch.u64(entry[0]).u64(entry[1]);
            }
            scratch.endRecord(record);
            out.write(scratch);
        }
        chunkInfos.add(new ChunkInfo(start, end, chunkOffset, chunkLength, indexOffsets, out.count() - indexStart,
                "", chunk.size(), chunk.size()));
        chunk.clear();
        chunkIndex.clear();
        chunkMessages = 0;
    }

    private static void writeSchema(RecordBuffer buffer, Schema schema) {
        int record = buffer.startRecord(Opcode.SCHEMA);
        buffer.u16(schema.id()).string(schema.name()).string(schema.encoding()).u32(schema.data().length)
                .raw(schema.data());
        buffer.endRecord(record);
    }

    private static void writeChannel(RecordBuffer buffer, Channel channel) {
        int record = buffer.startRecord(Opcode.CHANNEL);
        buffer.u16(channel.id()).u16(channel.schemaId()).string(channel.topic()).string(channel.messageEncoding())
                .stringMap(channel.metadata());
        buffer.endRecord(record);
    }

    private void ensureOpen() {
        if (closed) {
            throw new IllegalStateException("the MCAP writer is closed");
        }
    }

    /** Counts the bytes written and keeps the CRC32 of all of them (for the data end record). */
    private static final class CountingOutput implements Closeable {
        private final OutputStream out;
        private final CRC32 crc = new CRC32();
        private long count;

        CountingOutput(OutputStream out) {
            this.out = out;
        }

        void write(byte[] bytes) throws IOException {
            write(bytes, 0, bytes.length);
        }

        void write(RecordBuffer buffer) throws IOException {
            write(buffer.array(), 0, buffer.size());
        }

        void write(byte[] bytes, int offset, int length) throws IOException {
            out.write(bytes, offset, length);
            crc.update(bytes, offset, length);
            count += length;
        }

        long count() {
            return count;
        }

        long crc() {
            return crc.getValue();
        }

        void flush() throws IOException {
            out.flush();
        }

        @Override
        public void close() throws IOException {
            out.close();
        }
    }

    /** The text as UTF-8 bytes (for JSON messages and schemas). */
    public static byte[] utf8(String text) {
        return text.getBytes(StandardCharsets.UTF_8);
    }
}
