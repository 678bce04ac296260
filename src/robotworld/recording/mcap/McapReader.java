package robotworld.recording.mcap;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.zip.CRC32;

/**
 * Reads an MCAP file: its header, its summary (when the file was finished), and its data section record by
 * record in file order ({@link #cursor()}). Files whose writer died before finishing are read up to their last
 * complete record; {@link #finished()} tells them apart. See the package documentation for what is supported.
 */
public final class McapReader implements Closeable {

    /** Records larger than this are refused rather than read into memory. */
    static final long MAX_RECORD = 1L << 30;
    private static final int FOOTER_LENGTH = 1 + 8 + 8 + 8 + 4;

    private final Path path;
    private final FileChannel file;
    private final long size;
    private final String profile;
    private final String library;
    private final long dataStart;
    private final boolean finished;
    private final long summaryStart;
    private final long dataLimit;

    private McapReader(Path path, FileChannel file) throws IOException {
        this.path = path;
        this.file = file;
        this.size = file.size();
        byte[] magic = read(0, Math.min(8, size));
        if (magic.length < 8 || !Arrays.equals(magic, Opcode.MAGIC)) {
            throw new McapFormatException(path + " is not an MCAP file (it does not start with the MCAP magic)");
        }
        byte[] headerStart = read(8, Math.min(9, size - 8));
        if (headerStart.length < 9 || headerStart[0] != Opcode.HEADER) {
            throw new McapFormatException(8, "the first record is not a header");
        }
        long headerLength = new RecordReader(headerStart, 1, 9, 9).u64();
        if (headerLength > MAX_RECORD || 17 + headerLength > size) {
            throw new McapFormatException(8, "the header record is cut off");
        }
        RecordReader header = new RecordReader(read(17, headerLength), 0, (int) headerLength, 17);
        profile = header.string();
        library = header.string();
        dataStart = 17 + headerLength;
        long footerAt = size - 8 - FOOTER_LENGTH;
        boolean hasFooter = false;
        long summary = 0;
        if (footerAt >= dataStart) {
            byte[] tail = read(footerAt, FOOTER_LENGTH + 8);
            if (tail[0] == Opcode.FOOTER && Arrays.equals(Arrays.copyOfRange(tail, FOOTER_LENGTH, tail.length),
                    Opcode.MAGIC)) {
                RecordReader footer = new RecordReader(tail, 1, FOOTER_LENGTH, footerAt + 1);
                if (footer.u64() != 20) {
                    throw new McapFormatException(footerAt, "the footer record has the wrong length");
                }
                summary = footer.u64();
                hasFooter = true;
                if (summary != 0 && (summary < dataStart || summary > footerAt)) {
                    throw new McapFormatException(footerAt, "the footer points outside the file: " + summary);
                }
            }
        }
        finished = hasFooter;
        summaryStart = summary;
        dataLimit = !hasFooter ? size : summary != 0 ? summary : footerAt;
    }

    /**
     * Opens a file.
     *
     * @throws McapFormatException when it is not MCAP
     */
    public static McapReader open(Path path) throws IOException {
        FileChannel channel = FileChannel.open(path, StandardOpenOption.READ);
        try {
            return new McapReader(path, channel);
        } catch (IOException | RuntimeException e) {
            channel.close();
            throw e;
        }
    }

    /** The file read. */
    public Path path() {
        return path;
    }

    /** The header's profile. */
    public String profile() {
        return profile;
    }

    /** The header's library: who wrote the file. */
    public String library() {
        return library;
    }

    /** Whether the file ends with a footer: its writer finished it (else it died, or is still writing). */
    public boolean finished() {
        return finished;
    }

    /** The file's size in bytes. */
    public long size() {
        return size;
    }

    /**
     * The summary section, when the file has one.
     *
     * @throws McapFormatException when the summary is damaged
     */
    public Optional<Summary> summary() throws IOException {
        if (!finished || summaryStart == 0) {
            return Optional.empty();
        }
        long end = size - 8 - FOOTER_LENGTH;
        long length = end - summaryStart;
        if (length > MAX_RECORD) {
            throw new McapFormatException(summaryStart, "the summary section is larger than " + MAX_RECORD + " bytes");
        }
        byte[] bytes = read(summaryStart, length);
        List<Schema> schemas = new ArrayList<>();
        List<Channel> channels = new ArrayList<>();
        Statistics statistics = null;
        List<ChunkInfo> chunks = new ArrayList<>();
        List<Summary.AttachmentInfo> attachments = new ArrayList<>();
        List<String> metadata = new ArrayList<>();
        int position = 0;
        while (position < bytes.length) {
            RecordReader head = new RecordReader(bytes, position, bytes.length, summaryStart + position);
            int opcode = head.u8();
            long recordLength = head.u64();
            if (recordLength > head.remaining()) {
                throw new McapFormatException(summaryStart + position, "a summary record runs past the footer");
            }
            int contentStart = position + 9;
            RecordReader record = new RecordReader(bytes, contentStart, contentStart + (int) recordLength,
                    summaryStart + contentStart);
            switch (opcode) {
                case Opcode.SCHEMA -> {
                    Schema schema = schema(record);
                    if (schema != null) {
                        schemas.add(schema);
                    }
                }
                case Opcode.CHANNEL -> channels.add(channel(record));
                case Opcode.STATISTICS -> statistics = new Statistics(record.u64(), record.u16(), record.u32(),
                        record.u32(), record.u32(), record.u32(), record.u64(), record.u64(), record.u16u64Map());
                case Opcode.CHUNK_INDEX -> chunks.add(new ChunkInfo(record.u64(), record.u64(), record.u64(),
                        record.u64(), record.u16u64Map(), record.u64(), record.string(), record.u64(), record.u64()));
                case Opcode.ATTACHMENT_INDEX -> {
                    long offset = record.u64();
                    record.u64();
                    record.u64();
                    record.u64();
                    long dataSize = record.u64();
                    attachments.add(new Summary.AttachmentInfo(offset, record.string(), record.string(), dataSize));
                }
                case Opcode.METADATA_INDEX -> {
                    record.u64();
                    record.u64();
                    metadata.add(record.string());
                }
                default -> {
                    // summary offsets, and records this reader does not know
                }
            }
            position = contentStart + (int) recordLength;
        }
        return Optional.of(new Summary(schemas, channels, statistics, chunks, attachments, metadata));
    }

    /** A cursor over the data section, from its first record. */
    public Cursor cursor() {
        return new Cursor();
    }

    /**
     * Reads the whole data section and counts what it holds: the summary of a file that has none, and a check of
     * every record and CRC of one that has.
     */
    public Summary scan() throws IOException {
        Map<Integer, Schema> schemas = new LinkedHashMap<>();
        Map<Integer, Channel> channels = new LinkedHashMap<>();
        Map<Integer, Long> counts = new TreeMap<>();
        List<Summary.AttachmentInfo> attachments = new ArrayList<>();
        List<String> metadata = new ArrayList<>();
        long messages = 0;
        long start = 0;
        long end = 0;
        Cursor cursor = cursor();
        for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
            if (record instanceof Schema schema) {
                schemas.putIfAbsent(schema.id(), schema);
            } else if (record instanceof Channel channel) {
                channels.putIfAbsent(channel.id(), channel);
            } else if (record instanceof Message message) {
                start = messages == 0 ? message.logTime() : Math.min(start, message.logTime());
                end = Math.max(end, message.logTime());
                messages++;
                counts.merge(message.channelId(), 1L, Long::sum);
            } else if (record instanceof Attachment attachment) {
                attachments.add(new Summary.AttachmentInfo(cursor.recordOffset(), attachment.name(),
                        attachment.mediaType(), attachment.data().length));
            } else if (record instanceof Metadata data) {
                metadata.add(data.name());
            }
        }
        Statistics statistics = new Statistics(messages, schemas.size(), channels.size(), attachments.size(),
                metadata.size(), cursor.chunks(), start, end, counts);
        return new Summary(List.copyOf(schemas.values()), List.copyOf(channels.values()), statistics, List.of(),
                attachments, metadata);
    }

    /**
     * Reads one attachment by name (the first of that name), through the summary if there is one, else by a scan.
     */
    public Optional<Attachment> attachment(String name) throws IOException {
        Cursor cursor = cursor();
        for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
            if (record instanceof Attachment attachment && attachment.name().equals(name)) {
                return Optional.of(attachment);
            }
        }
        return Optional.empty();
    }

    /** The first metadata record of that name, found by a scan. */
    public Optional<Metadata> metadata(String name) throws IOException {
        Cursor cursor = cursor();
        for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
            if (record instanceof Metadata metadata && metadata.name().equals(name)) {
                return Optional.of(metadata);
            }
        }
        return Optional.empty();
    }

    @Override
    public void close() throws IOException {
        file.close();
    }

    private byte[] read(long offset, long length) throws IOException {
        if (length < 0 || length > MAX_RECORD) {
            throw new McapFormatException(offset, "a record of " + length + " bytes is beyond what this reader takes");
        }
        ByteBuffer buffer = ByteBuffer.allocate((int) length);
        while (buffer.hasRemaining()) {
            int n = file.read(buffer, offset + buffer.position());
            if (n < 0) {
                break;
            }
        }
        return buffer.position() == length ? buffer.array() : Arrays.copyOf(buffer.array(), buffer.position());
    }

    private static Schema schema(RecordReader record) throws McapFormatException {
        int id = record.u16();
        String name = record.string();
        String encoding = record.string();
        byte[] data = record.bytes(record.u32());
        return id == 0 ? null : new Schema(id, name, encoding, data); // id 0 is invalid: readers ignore it
    }

    private static Channel channel(RecordReader record) throws McapFormatException {
        return new Channel(record.u16(), record.u16(), record.string(), record.string(), record.stringMap());
    }

    /**
     * Walks the data section in file order, record by record, opening chunks. Not thread-safe.
     */
    public final class Cursor {
        private long position = dataStart;
        private byte[] chunk;
        private int chunkPosition;
        private long chunkFileOffset;
        private long recordOffset;
        private long chunks;
        private boolean ended;
        private long cutOffAt = -1;

        private Cursor() {
        }

        /**
         * The next schema, channel, message, attachment or metadata record, or null at the end of the data section
         * (or, in an unfinished file, at its last complete record: see {@link #cutOffAt()}).
         *
         * @throws McapFormatException when a record is damaged, or a chunk's compression is unknown or damaged
         */
        public DataRecord next() throws IOException {
            while (true) {
                if (chunk != null) {
                    DataRecord inChunk = nextInChunk();
                    if (inChunk != null) {
                        return inChunk;
                    }
                    chunk = null;
                }
                if (ended || position >= dataLimit) {
                    return null;
                }
                if (position + 9 > dataLimit) {
                    return cutOff();
                }
                recordOffset = position;
                RecordReader head = new RecordReader(read(position, 9), 0, 9, position);
                int opcode = head.u8();
                long length = head.u64();
                if (length > dataLimit - position - 9) {
                    return cutOff();
                }
                long contentAt = position + 9;
                position = contentAt + length;
                switch (opcode) {
                    case Opcode.DATA_END, Opcode.FOOTER -> {
                        ended = true;
                        return null;
                    }
                    case Opcode.SCHEMA, Opcode.CHANNEL, Opcode.MESSAGE, Opcode.ATTACHMENT, Opcode.METADATA -> {
                        DataRecord record = decode(opcode, new RecordReader(read(contentAt, length), 0, (int) length,
                                contentAt));
                        if (record != null) {
                            return record;
                        }
                    }
                    case Opcode.CHUNK -> openChunk(contentAt, length);
                    default -> {
                        // indexes (read from the summary) and records this reader does not know: skip
                    }
                }
            }
        }

        /** Where the file was cut off (an unfinished file's incomplete last record), or -1. */
        public long cutOffAt() {
            return cutOffAt;
        }

        /** Chunks opened so far. */
        public long chunks() {
            return chunks;
        }

        /** Where the record last returned starts (its chunk's start, for a record inside a chunk). */
        long recordOffset() {
            return recordOffset;
        }

        private DataRecord cutOff() throws McapFormatException {
            if (finished) {
                throw new McapFormatException(position, "a record runs past the end of the data section");
            }
            cutOffAt = position;
            ended = true;
            return null;
        }

        private void openChunk(long contentAt, long length) throws IOException {
            byte[] content = read(contentAt, length);
            RecordReader record = new RecordReader(content, 0, (int) length, contentAt);
            record.u64();
            record.u64();
            long uncompressedSize = record.u64();
            long crc = record.u32();
            String compression = record.string();
            long recordsLength = record.u64();
            if (compression.isEmpty() && recordsLength != uncompressedSize) {
                throw new McapFormatException(contentAt, "an uncompressed chunk of " + recordsLength
                        + " bytes says it holds " + uncompressedSize);
            }
            int from = record.position();
            if (recordsLength > record.remaining()) {
                throw new McapFormatException(contentAt, "a chunk's records run past the chunk");
            }
            byte[] bytes = compression.isEmpty() ? Arrays.copyOfRange(content, from, from + (int) recordsLength)
                    : ChunkCompression.open(compression, content, from, (int) recordsLength, uncompressedSize,
                            contentAt);
            if (crc != 0) {
                CRC32 check = new CRC32();
                check.update(bytes);
                if (check.getValue() != crc) {
                    throw new McapFormatException(contentAt, "a chunk's CRC does not match its records: damaged");
                }
            }
            chunk = bytes;
            chunkPosition = 0;
            chunkFileOffset = contentAt + from; // in a compressed chunk, offsets in messages count uncompressed bytes
            chunks++;
        }

        private DataRecord nextInChunk() throws McapFormatException {
            while (chunkPosition < chunk.length) {
                RecordReader head = new RecordReader(chunk, chunkPosition, chunk.length, chunkFileOffset + chunkPosition);
                int opcode = head.u8();
                long length = head.u64();
                if (length > head.remaining()) {
                    throw new McapFormatException(chunkFileOffset + chunkPosition, "a record runs past its chunk");
                }
                int contentAt = chunkPosition + 9;
                chunkPosition = contentAt + (int) length;
                if (opcode == Opcode.SCHEMA || opcode == Opcode.CHANNEL || opcode == Opcode.MESSAGE) {
                    DataRecord record = decode(opcode, new RecordReader(chunk, contentAt, chunkPosition,
                            chunkFileOffset + contentAt));
                    if (record != null) {
                        return record;
                    }
                }
            }
            return null;
        }

        private DataRecord decode(int opcode, RecordReader record) throws McapFormatException {
            switch (opcode) {
                case Opcode.SCHEMA:
                    return schema(record);
                case Opcode.CHANNEL:
                    return channel(record);
                case Opcode.MESSAGE:
                    return new Message(record.u16(), record.u32(), record.u64(), record.u64(), record.rest());
                case Opcode.ATTACHMENT: {
                    long logTime = record.u64();
                    long createTime = record.u64();
                    String name = record.string();
                    String mediaType = record.string();
                    byte[] data = record.bytes(record.u64());
                    record.u32();
                    return new Attachment(logTime, createTime, name, mediaType, data);
                }
                case Opcode.METADATA:
                    return new Metadata(record.string(), record.stringMap());
                default:
                    return null;
            }
        }
    }
}
