package robotworld.recording.mcap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The writer and reader against each other, and against damaged and unfinished files. */
class McapRoundTripTest {

    @TempDir
    Path temp;

    /** Writes {@code count} messages on two channels, with small chunks so there are several. */
    static Path sample(Path file, int count, int chunkSize) throws IOException {
        try (McapWriter writer = McapWriter.create(file, McapWriter.Options.defaults().chunkSize(chunkSize))) {
            int schema = writer.addSchema("test.Value", "jsonschema",
                    "{\"type\":\"object\"}".getBytes(StandardCharsets.UTF_8));
            int a = writer.addChannel("/a", "json", schema, Map.of("kind", "first"));
            int b = writer.addChannel("/b", "json", schema, Map.of());
            writer.addMetadata(new Metadata("rwe.test", Map.of("world", "W", "note", "ü")));
            writer.addAttachment(new Attachment(5, 0, "world.xml", "application/xml",
                    "<RobotWorld/>".getBytes(StandardCharsets.UTF_8)));
            for (int i = 0; i < count; i++) {
                writer.addMessage(i % 3 == 0 ? b : a, i + 1, 1_000_000_000L + i * 1000L, 1_000_000_000L + i * 1000L,
                        ("{\"i\":" + i + "}").getBytes(StandardCharsets.UTF_8));
            }
        }
        return file;
    }

    @Test
    void whatIsWrittenIsReadBackWithItsSummary() throws IOException {
        Path file = sample(temp.resolve("a.mcap"), 1000, 4096);
        try (McapReader reader = McapReader.open(file)) {
            assertTrue(reader.finished());
            assertEquals("RobotWorldExplorer", reader.library());
            Summary summary = reader.summary().orElseThrow();
            assertEquals(1, summary.schemas().size());
            assertEquals(List.of("/a", "/b"), summary.channels().stream().map(Channel::topic).toList());
            assertEquals(Map.of("kind", "first"), summary.channel(0).metadata());
            Statistics statistics = summary.statistics();
            assertEquals(1000, statistics.messageCount());
            assertEquals(1_000_000_000L, statistics.messageStartTime());
            assertEquals(1_000_000_000L + 999_000L, statistics.messageEndTime());
            assertEquals(Map.of(0, 666L, 1, 334L), statistics.channelMessageCounts());
            assertTrue(statistics.chunkCount() > 3, "small chunks: " + statistics.chunkCount());
            assertEquals(statistics.chunkCount(), summary.chunks().size());
            assertEquals(List.of("world.xml"), summary.attachments().stream().map(Summary.AttachmentInfo::name)
                    .toList());
            assertEquals(List.of("rwe.test"), summary.metadata());

            List<Message> messages = messages(reader);
            assertEquals(1000, messages.size());
            for (int i = 0; i < 1000; i++) {
                assertEquals("{\"i\":" + i + "}", messages.get(i).text());
                assertEquals(i + 1, messages.get(i).sequence());
            }
            assertEquals(1000, reader.scan().statistics().messageCount());
            assertEquals("<RobotWorld/>", new String(reader.attachment("world.xml").orElseThrow().data(),
                    StandardCharsets.UTF_8));
            assertEquals("ü", reader.metadata("rwe.test").orElseThrow().values().get("note"));
        }
    }

    @Test
    void anEmptyRecordingIsValid() throws IOException {
        Path file = temp.resolve("empty.mcap");
        new McapWriter(Files.newOutputStream(file), McapWriter.Options.defaults()).close();
        try (McapReader reader = McapReader.open(file)) {
            assertTrue(reader.finished());
            assertEquals(0, reader.summary().orElseThrow().statistics().messageCount());
            assertNull(reader.cursor().next());
        }
    }

    @Test
    void anUnfinishedFileIsReadUpToItsLastCompleteRecord() throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        McapWriter writer = new McapWriter(bytes, McapWriter.Options.defaults());
        int schema = writer.addSchema("s", "jsonschema", new byte[0]);
        int channel = writer.addChannel("/t", "json", schema, Map.of());
        for (int i = 0; i < 10; i++) {
            writer.addMessage(channel, 0, i, i, new byte[] {'1'});
        }
        writer.flush(); // what a recorder does every second; then the program dies
        int firstChunkEnds = bytes.size();
        for (int i = 0; i < 5; i++) {
            writer.addMessage(channel, 0, 100 + i, 100 + i, new byte[] {'2'});
        }
        writer.flush();
        byte[] all = bytes.toByteArray();
        Path cut = temp.resolve("cut.mcap");
        Files.write(cut, Arrays.copyOf(all, firstChunkEnds + 40)); // the second chunk is incomplete
        try (McapReader reader = McapReader.open(cut)) {
            assertFalse(reader.finished());
            assertTrue(reader.summary().isEmpty());
            McapReader.Cursor cursor = reader.cursor();
            List<Message> messages = new ArrayList<>();
            for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
                if (record instanceof Message message) {
                    messages.add(message);
                }
            }
            assertEquals(10, messages.size());
            assertTrue(cursor.cutOffAt() > 0);
        }
    }

    @Test
    void aDamagedChunkIsAnErrorNamingWhere() throws IOException {
        Path file = sample(temp.resolve("ok.mcap"), 50, 1 << 20);
        byte[] bytes = Files.readAllBytes(file);
        int at = indexOf(bytes, "{\"i\":25}".getBytes(StandardCharsets.UTF_8));
        bytes[at + 5] = '7';
        Path damaged = temp.resolve("damaged.mcap");
        Files.write(damaged, bytes);
        try (McapReader reader = McapReader.open(damaged)) {
            McapFormatException e = assertThrows(McapFormatException.class, () -> messages(reader));
            assertTrue(e.getMessage().contains("CRC") && e.getMessage().startsWith("at byte "), e.getMessage());
        }
    }

    @Test
    void somethingElseIsNotTakenForMcap() throws IOException {
        Path text = temp.resolve("notes.mcap");
        Files.writeString(text, "just some text, long enough to have a footer's worth of bytes in it........");
        McapFormatException e = assertThrows(McapFormatException.class, () -> McapReader.open(text));
        assertTrue(e.getMessage().contains("not an MCAP file"), e.getMessage());
    }

    @Test
    void unknownRecordsAreSkipped() throws IOException {
        Path file = sample(temp.resolve("plain.mcap"), 3, 1 << 20);
        byte[] bytes = Files.readAllBytes(file);
        // a private record (opcode 0x80) right after the header
        int headerEnd = 8 + 9 + (int) littleEndian(bytes, 9);
        byte[] privateRecord = {(byte) 0x80, 3, 0, 0, 0, 0, 0, 0, 0, 'x', 'y', 'z'};
        byte[] changed = new byte[bytes.length + privateRecord.length];
        System.arraycopy(bytes, 0, changed, 0, headerEnd);
        System.arraycopy(privateRecord, 0, changed, headerEnd, privateRecord.length);
        System.arraycopy(bytes, headerEnd, changed, headerEnd + privateRecord.length, bytes.length - headerEnd);
        // without the footer (whose offsets no longer fit), it is read as a stream
        Path stream = temp.resolve("stream.mcap");
        Files.write(stream, Arrays.copyOf(changed, changed.length - 8 - 29));
        try (McapReader reader = McapReader.open(stream)) {
            List<Message> messages = messages(reader);
            assertEquals(3, messages.size());
            assertArrayEquals("{\"i\":2}".getBytes(StandardCharsets.UTF_8), messages.get(2).data());
        }
    }

    static List<Message> messages(McapReader reader) throws IOException {
        List<Message> messages = new ArrayList<>();
        McapReader.Cursor cursor = reader.cursor();
        for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
            if (record instanceof Message message) {
                messages.add(message);
            }
        }
        return messages;
    }

    private static long littleEndian(byte[] bytes, int at) {
        long value = 0;
        for (int i = 0; i < 8; i++) {
            value |= (long) (bytes[at + i] & 0xFF) << (8 * i);
        }
        return value;
    }

    private static int indexOf(byte[] haystack, byte[] needle) {
        outer:
        for (int i = 0; i <= haystack.length - needle.length; i++) {
            for (int j = 0; j < needle.length; j++) {
                if (haystack[i + j] != needle[j]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new AssertionError("not found");
    }
}
