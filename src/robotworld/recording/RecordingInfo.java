package robotworld.recording;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import robotworld.recording.mcap.Channel;
import robotworld.recording.mcap.McapReader;
import robotworld.recording.mcap.Metadata;
import robotworld.recording.mcap.Schema;
import robotworld.recording.mcap.Statistics;
import robotworld.recording.mcap.Summary;

/**
 * What a recording holds, for {@code rwe record --info}: who wrote it, the world, the time range, and per channel
 * its schema and message count. Reads the summary of a finished file; scans a file whose writer did not finish.
 *
 * @param file        the file
 * @param size        its size in bytes
 * @param library     who wrote it
 * @param finished    whether it has its summary and footer
 * @param cutOffAt    for an unfinished file, where its last complete record ends (-1 when not cut off)
 * @param summary     what it holds
 * @param start       the start metadata (world, space, host, started), empty if none
 * @param end         the end metadata (messages, dropped, why), empty if none
 */
public record RecordingInfo(Path file, long size, String library, boolean finished, long cutOffAt, Summary summary,
                            Map<String, String> start, Map<String, String> end) {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS",
            Locale.ROOT).withZone(ZoneId.systemDefault());

    /**
     * Reads what {@code file} holds.
     *
     * @throws robotworld.recording.mcap.McapFormatException when it is no MCAP file or is damaged
     */
    public static RecordingInfo of(Path file) throws IOException {
        try (McapReader reader = McapReader.open(file)) {
            Optional<Summary> summary = reader.summary();
            long cutOff = -1;
            Summary found;
            if (summary.isPresent() && summary.get().statistics() != null) {
                found = summary.get();
            } else {
                found = reader.scan();
                McapReader.Cursor cursor = reader.cursor();
                while (cursor.next() != null) {
                    // to the end, to learn where the file was cut off
                }
                cutOff = cursor.cutOffAt();
            }
            Map<String, String> start = reader.metadata(RecordingFormat.START_METADATA).map(Metadata::values)
                    .orElse(Map.of());
            Map<String, String> end = reader.metadata(RecordingFormat.END_METADATA).map(Metadata::values)
                    .orElse(Map.of());
            return new RecordingInfo(file, reader.size(), reader.library(), reader.finished(), cutOff, found, start,
                    end);
        }
    }

    /** Prints it for people. */
    public void print(PrintWriter out) {
        Statistics stats = summary.statistics();
        out.println(file + ": " + (finished ? "finished" : "UNFINISHED (its writer did not close it; read up to byte "
                + (cutOffAt < 0 ? size : cutOffAt) + ")") + " MCAP file, " + size + " bytes, written by " + library);
        if (!start.isEmpty()) {
            out.println("world        " + start.getOrDefault("world", "?") + " (from " + start.getOrDefault("space", "?")
                    + " on " + start.getOrDefault("host", "?") + ")");
        }
        if (stats.messageCount() > 0) {
            Instant from = Instant.ofEpochSecond(0, stats.messageStartTime());
            Instant to = Instant.ofEpochSecond(0, stats.messageEndTime());
            out.printf(Locale.ROOT, "time         %s .. %s (%.3f s)%n", TIME.format(from), TIME.format(to),
                    Duration.between(from, to).toNanos() / 1e9);
        } else {
            out.println("time         no messages");
        }
        out.println("messages     " + stats.messageCount() + " in " + stats.chunkCount() + " chunk(s)"
                + (end.containsKey("dropped") ? "; " + end.get("dropped") + " dropped while recording" : "")
                + (end.containsKey("why") ? "; ended: " + end.get("why") : ""));
        out.println("channels     " + summary.channels().size());
        List<Channel> channels = summary.channels();
        int width = channels.stream().mapToInt(c -> c.topic().length()).max().orElse(10);
        int schemaWidth = summary.schemas().stream().mapToInt(s -> s.name().length()).max().orElse(11);
        for (Channel channel : channels) {
            Schema schema = summary.schema(channel.schemaId());
            long count = stats.channelMessageCounts().getOrDefault(channel.id(), 0L);
            out.printf(Locale.ROOT, "  %-" + width + "s  %-" + schemaWidth + "s  %-5s %8d%n", channel.topic(),
                    schema == null ? "(no schema)" : schema.name(), channel.messageEncoding(), count);
        }
        if (!summary.attachments().isEmpty()) {
            out.println("attachments  " + String.join(", ", summary.attachments().stream()
                    .map(a -> a.name() + " (" + a.mediaType() + ", " + a.size() + " bytes)").toList()));
        }
        if (!summary.metadata().isEmpty()) {
            out.println("metadata     " + String.join(", ", summary.metadata()));
        }
        out.println("indexed      " + (summary.chunks().isEmpty() ? "no (read linearly)" : "yes, "
                + summary.chunks().size() + " chunk index(es)"));
        out.flush();
    }
}
