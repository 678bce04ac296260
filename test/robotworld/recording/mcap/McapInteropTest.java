package robotworld.recording.mcap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;

/** Our writer against the reference Python reader, and the reference Python writer against our reader. */
class McapInteropTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path temp;

    @Test
    void theReferenceReaderReadsEverythingWeWrite() throws Exception {
        McapPeer peer = McapPeer.require();
        Path file = McapRoundTripTest.sample(temp.resolve("ours.mcap"), 2000, 8192);
        JsonNode found = peer.read(file);

        assertEquals("RobotWorldExplorer", found.at("/header/library").asText());
        JsonNode summary = found.get("summary");
        assertEquals("test.Value", summary.at("/schemas/0/name").asText());
        assertEquals("jsonschema", summary.at("/schemas/0/encoding").asText());
        assertEquals("/a", summary.at("/channels/0/topic").asText());
        assertEquals("first", summary.at("/channels/0/metadata/kind").asText());
        assertEquals(2000, summary.at("/statistics/message_count").asLong());
        assertEquals(1333, summary.at("/statistics/channel_message_counts/0").asLong());
        long chunks = summary.at("/statistics/chunk_count").asLong();
        assertTrue(chunks > 3);
        assertEquals(chunks, summary.get("chunk_indexes").asLong());
        assertEquals("world.xml", summary.at("/attachment_indexes/0").asText());
        assertEquals("rwe.test", summary.at("/metadata_indexes/0").asText());
        // through the index, in log-time order
        JsonNode indexed = found.get("indexed");
        assertEquals(2000, indexed.size());
        for (int i = 0; i < 2000; i++) {
            assertEquals("{\"i\":" + i + "}", indexed.get(i).get("data").asText());
            assertEquals(1_000_000_000L + i * 1000L, indexed.get(i).get("log_time").asLong());
            assertEquals(i % 3 == 0 ? "/b" : "/a", indexed.get(i).get("topic").asText());
        }
        // linearly, every CRC checked, up to the footer
        assertEquals(2000, found.get("streamed").size());
        assertTrue(found.get("footer").asBoolean());
        assertEquals("<RobotWorld/>", found.at("/attachments/0/data").asText());
        assertEquals("ü", found.at("/metadata/0/metadata/note").asText());
    }

    @Test
    void weReadWhatTheReferenceWriterWrites() throws Exception {
        McapPeer peer = McapPeer.require();
        Path file = temp.resolve("theirs.mcap");
        peer.write(file, spec("none"), temp);
        try (McapReader reader = McapReader.open(file)) {
            assertTrue(reader.finished());
            assertEquals("python mcap peer", reader.library());
            Summary summary = reader.summary().orElseThrow();
            assertEquals(300, summary.statistics().messageCount());
            assertEquals(List.of("/x", "/y"), summary.channels().stream().map(Channel::topic).toList());
            List<Message> messages = McapRoundTripTest.messages(reader);
            assertEquals(300, messages.size());
            assertEquals("{\"n\":299}", messages.get(299).text());
            assertEquals("hello", new String(reader.attachment("notes.txt").orElseThrow().data(),
                    StandardCharsets.UTF_8));
            assertEquals("W", reader.metadata("info").orElseThrow().values().get("world"));
            assertEquals(300, reader.scan().statistics().messageCount());
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"zstd", "lz4"})
    void weReadChunksTheReferenceWriterCompressed(String compression) throws Exception {
        McapPeer peer = McapPeer.require();
        Path file = temp.resolve(compression + ".mcap");
        peer.write(file, spec(compression), temp);
        try (McapReader reader = McapReader.open(file)) {
            Summary summary = reader.summary().orElseThrow();
            assertTrue(summary.chunks().size() > 3, "several chunks: " + summary.chunks().size());
            assertTrue(summary.chunks().stream().allMatch(c -> c.compression().equals(compression)),
                    summary.chunks().toString());
            List<Message> messages = McapRoundTripTest.messages(reader);
            assertEquals(300, messages.size());
            for (int n = 0; n < 300; n++) {
                assertEquals("{\"n\":" + n + "}", messages.get(n).text());
                assertEquals(5_000L + n, messages.get(n).logTime());
            }
            assertEquals(summary.chunks().size(), reader.scan().statistics().chunkCount());
        }
    }

    @Test
    void anUnknownCompressionOrADamagedChunkIsAnErrorNeverAWrongResult() throws Exception {
        McapPeer peer = McapPeer.require();
        Path file = temp.resolve("zstd.mcap");
        peer.write(file, spec("zstd"), temp);
        byte[] bytes = java.nio.file.Files.readAllBytes(file);
        int name = indexOf(bytes, new byte[] {4, 0, 0, 0, 'z', 's', 't', 'd'}); // the first chunk's compression
        assertTrue(name > 0);

        byte[] unknown = bytes.clone();
        unknown[name + 4] = 'x';
        McapFormatException e = assertThrows(McapFormatException.class, () -> messagesOf(unknown, "unknown.mcap"));
        assertTrue(e.getMessage().contains("compressed with 'xstd'"), e.getMessage());

        byte[] damaged = bytes.clone();
        damaged[name + 8 + 8 + 20] ^= 0x5A; // inside the compressed records
        e = assertThrows(McapFormatException.class, () -> messagesOf(damaged, "damaged.mcap"));
        assertTrue(e.getMessage().contains("zstd chunk") || e.getMessage().contains("CRC"), e.getMessage());
    }

    private List<Message> messagesOf(byte[] bytes, String name) throws Exception {
        Path file = temp.resolve(name);
        java.nio.file.Files.write(file, bytes);
        try (McapReader reader = McapReader.open(file)) {
            return McapRoundTripTest.messages(reader);
        }
    }

    private static int indexOf(byte[] bytes, byte[] wanted) {
        outer:
        for (int i = 0; i + wanted.length <= bytes.length; i++) {
            for (int j = 0; j < wanted.length; j++) {
                if (bytes[i + j] != wanted[j]) {
                    continue outer;
                }
            }
            return i;
        }
        return -1;
    }

    private static JsonNode spec(String compression) {
        ObjectNode spec = JSON.createObjectNode();
        spec.put("compression", compression);
        spec.put("chunk_size", 2048);
        ArrayNode schemas = spec.putArray("schemas");
        schemas.addObject().put("name", "test.N").put("encoding", "jsonschema").put("data", "{\"type\":\"object\"}");
        ArrayNode channels = spec.putArray("channels");
        channels.addObject().put("topic", "/x").put("message_encoding", "json").put("schema", "test.N");
        channels.addObject().put("topic", "/y").put("message_encoding", "json").put("schema", "test.N");
        spec.putArray("attachments").addObject().put("name", "notes.txt").put("media_type", "text/plain")
                .put("data", "hello").put("log_time", 1);
        spec.putArray("metadata").addObject().put("name", "info").putObject("metadata").put("world", "W");
        ArrayNode messages = spec.putArray("messages");
        for (int n = 0; n < 300; n++) {
            messages.addObject().put("topic", n % 2 == 0 ? "/x" : "/y").put("log_time", 5_000L + n)
                    .put("data", "{\"n\":" + n + "}");
        }
        return spec;
    }
}
