package robotworld.recording;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldObserver;
import robotworld.recording.mcap.Attachment;
import robotworld.recording.mcap.McapWriter;
import robotworld.recording.mcap.Metadata;
import robotworld.telemetry.TelemetryMessage;
import robotworld.telemetry.Topic;
import robotworld.telemetry.Topics;
import robotworld.telemetry.TrafficJson;
import robotworld.telemetry.WorldTelemetry;

/**
 * Writes a world's traffic into an MCAP file (the contract is in the package documentation).
 *
 * <pre>{@code
 * try (WorldTap tap = new WorldTap(space, layout);
 *      Recorder recorder = Recorder.start(file, new Recorder.Start(layout, spaceUrl, worldXml), Recorder.Options.defaults())) {
 *     tap.add(recorder.observer()).start();
 *     ...                       // recorder.status() for progress
 * }                             // the tap stops first, then the recorder finishes the file
 * }</pre>
 */
public final class Recorder implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(Recorder.class);
    private static final long BEHIND_NANOS = 1_000_000_000L;

    /**
     * How a recorder works.
     *
     * @param queueCapacity messages that may wait for the writing thread before new ones are dropped (and counted)
     * @param flushEvery    how often the file is brought up to date on disk
     * @param chunkSize     MCAP chunk size in bytes
     */
    public record Options(int queueCapacity, Duration flushEvery, int chunkSize) {

        /** Checks the values. */
        public Options {
            if (queueCapacity < 1 || flushEvery.isNegative() || flushEvery.isZero() || chunkSize < 1) {
                throw new IllegalArgumentException("queue, flush period and chunk size must be positive");
            }
        }

        /** 65 536 messages of queue, flushed every second, 512 KiB chunks. */
        public static Options defaults() {
            return new Options(65_536, Duration.ofSeconds(1), 512 * 1024);
        }

        /** With another queue capacity. */
        public Options queueCapacity(int capacity) {
            return new Options(capacity, flushEvery, chunkSize);
        }
    }

    /**
     * What the recording is of.
     *
     * @param layout   the world recorded
     * @param space    the space's URL, for the metadata
     * @param worldXml the world's description, or null when not known
     */
    public record Start(WorldLayout layout, String space, byte[] worldXml) {
        /** Checks the fields. */
        public Start {
            Objects.requireNonNull(layout, "layout");
            Objects.requireNonNull(space, "space");
        }
    }

    /**
     * How far the recording is.
     *
     * @param messages written to the file
     * @param bytes    the file's size so far (what is flushed and what waits in the current chunk)
     * @param dropped  messages the recorder could not keep (its queue was full), plus events the tap reported lost
     * @param queued   messages waiting for the writing thread
     * @param elapsed  since the recording started
     * @param behind   whether the writing thread falls behind (its queue is more than half full, or it dropped a
     *                 message within the last second)
     * @param failure  why writing failed (then nothing more is written), or null
     */
    public record Status(long messages, long bytes, long dropped, int queued, Duration elapsed, boolean behind,
                         String failure) {
    }

    private final Path file;
    private final McapWriter writer;
    private final Options options;
    private final BlockingQueue<TelemetryMessage> queue;
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicLong tapLost = new AtomicLong();
    private final long startedNanos = System.nanoTime();
    private final Thread thread;
    private final WorldObserver observer;
    private volatile boolean closing;
    private volatile String failure;
    private volatile long written;
    private volatile long bytes;
    private volatile long lastDropNanos = System.nanoTime() - 2 * BEHIND_NANOS;

    // ---- the writing thread's state ----
    private final Map<String, Integer> schemaIds = new HashMap<>();
    private final Map<String, Integer> channelIds = new HashMap<>();
    private final Map<Integer, Long> sequences = new HashMap<>();
    private long droppedReported;

    private Recorder(Path file, McapWriter writer, Options options) {
        this.file = file;
        this.writer = writer;
        this.options = options;
        this.queue = new ArrayBlockingQueue<>(options.queueCapacity());
        WorldTelemetry telemetry = new WorldTelemetry(this::offer);
        this.observer = new WorldObserver() {
            @Override
            public void requestSeen(robotworld.observe.RequestSeen event) {
                telemetry.requestSeen(event);
            }

            @Override
            public void answerSeen(robotworld.observe.AnswerSeen event) {
                telemetry.answerSeen(event);
            }

            @Override
            public void liveness(robotworld.observe.Liveness event) {
                telemetry.liveness(event);
            }

            @Override
            public void actuatorStopped(robotworld.observe.ActuatorStopped event) {
                telemetry.actuatorStopped(event);
            }

            @Override
            public void groundTruth(robotworld.observe.GroundTruth frame) {
                telemetry.groundTruth(frame);
            }

            @Override
            public void gap(robotworld.observe.Gap gap) {
                if (gap.missed() > 0) {
                    tapLost.addAndGet(gap.missed());
                }
                telemetry.gap(gap);
            }
        };
        this.thread = new Thread(this::run, "recorder " + file.getFileName());
        thread.setDaemon(true);
    }

    /**
     * Creates {@code file} (replacing it), writes what the recording is of, and starts the writing thread.
     *
     * @throws IOException when the file cannot be written
     */
    public static Recorder start(Path file, Start start, Options options) throws IOException {
        McapWriter writer = McapWriter.create(file, McapWriter.Options.defaults().chunkSize(options.chunkSize())
                .library("RobotWorldExplorer recorder (" + RecordingFormat.FORMAT + ")"));
        try {
            Instant now = Instant.now();
            long nanos = WorldTelemetry.nanos(now);
            Map<String, String> metadata = new LinkedHashMap<>();
            metadata.put("format", RecordingFormat.FORMAT);
            metadata.put("world", start.layout().world());
            metadata.put("started", now.toString());
            metadata.put("space", start.space());
            metadata.put("host", robotworld.core.HostNames.thisComputer());
            writer.addMetadata(new Metadata(RecordingFormat.START_METADATA, metadata));
            writer.addAttachment(new Attachment(nanos, nanos, RecordingFormat.LAYOUT_ATTACHMENT, "application/json",
                    RecordingFormat.layoutJson(start.layout())));
            if (start.worldXml() != null) {
                writer.addAttachment(new Attachment(nanos, nanos, RecordingFormat.WORLD_ATTACHMENT,
                        "application/xml", start.worldXml()));
            }
            Recorder recorder = new Recorder(file, writer, options);
            // every topic known in advance gets its channel now, so tools list them even before traffic
            for (Topic topic : Topics.known(start.layout())) {
                recorder.channel(topic);
            }
            writer.flush();
            recorder.bytes = writer.bytesWritten();
            recorder.thread.start();
            return recorder;
        } catch (IOException | RuntimeException e) {
            try {
                writer.close();
            } catch (IOException ignored) {
                // already failing
            }
            throw e;
        }
    }

    /** The observer to add to the tap. */
    public WorldObserver observer() {
        return observer;
    }

    /** The file written. */
    public Path file() {
        return file;
    }

    /**
     * Queues a message for writing; never blocks.
     *
     * @return false when it was dropped (the queue was full, writing failed, or the recorder is closed): counted
     */
    public boolean offer(TelemetryMessage message) {
        if (closing || failure != null || !queue.offer(message)) {
            dropped.incrementAndGet();
            lastDropNanos = System.nanoTime();
            return false;
        }
        return true;
    }

    /** How far the recording is. */
    public Status status() {
        long lost = dropped.get() + tapLost.get();
        int waiting = queue.size();
        return new Status(written, bytes, lost, waiting, Duration.ofNanos(System.nanoTime() - startedNanos),
                waiting > options.queueCapacity() / 2 || System.nanoTime() - lastDropNanos < BEHIND_NANOS, failure);
    }

    /** Finishes the file: stops taking messages, writes what waits, the closing metadata, summary and footer. */
    @Override
    public void close() throws IOException {
        close("stopped");
    }

    /** As {@link #close()}, saying why recording ended (e.g. "Ctrl-C", "--duration reached"). */
    public void close(String why) throws IOException {
        if (closing) {
            return;
        }
        closing = true;
        thread.interrupt();
        try {
            thread.join(30_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        synchronized (writer) {
            if (failure == null) {
                drain();
                Map<String, String> end = new LinkedHashMap<>();
                end.put("ended", Instant.now().toString());
                end.put("messages", String.valueOf(written));
                end.put("dropped", String.valueOf(dropped.get() + tapLost.get()));
                end.put("why", why);
                writer.addMetadata(new Metadata(RecordingFormat.END_METADATA, end));
            }
            writer.close();
            bytes = file.toFile().length();
        }
    }

    // ---- the writing thread ----

    private void run() {
        long flushNanos = options.flushEvery().toNanos();
        long lastFlush = System.nanoTime();
        try {
            while (!closing) {
                TelemetryMessage message = queue.poll(Math.max(1, flushNanos / 4), TimeUnit.NANOSECONDS);
                synchronized (writer) {
                    if (message != null) {
                        write(message);
                        drainSome(4096);
                    }
                    reportDrops();
                    if (System.nanoTime() - lastFlush >= flushNanos) {
                        writer.flush();
                        lastFlush = System.nanoTime();
                    }
                    bytes = writer.bytesWritten() + writer.bytesPending();
                }
            }
        } catch (InterruptedException e) {
            // closing
        } catch (IOException | RuntimeException e) {
            failure = "writing " + file + " failed: " + e.getMessage();
            LOG.error(failure, e);
            queue.clear();
        }
    }

    private void drain() throws IOException {
        drainSome(Integer.MAX_VALUE);
        reportDrops();
    }

    private void drainSome(int most) throws IOException {
        for (int i = 0; i < most; i++) {
            TelemetryMessage next = queue.poll();
            if (next == null) {
                return;
            }
            write(next);
        }
    }

    /** Writes a gap message for messages this recorder dropped since the last one: a drop is never silent. */
    private void reportDrops() throws IOException {
        long now = dropped.get();
        if (now > droppedReported) {
            long missed = now - droppedReported;
            droppedReported = now;
            ObjectNode gap = TrafficJson.MAPPER.createObjectNode();
            gap.putNull("participant");
            gap.putNull("module");
            gap.put("missed", missed);
            gap.put("why", missed + " messages dropped: the recorder fell behind (" + now + " in all)");
            gap.put("ended", false);
            write(new TelemetryMessage(Topics.GAPS, WorldTelemetry.nanos(Instant.now()), TrafficJson.bytes(gap)));
        }
    }

    private void write(TelemetryMessage message) throws IOException {
        int channel = channel(message.topic());
        long sequence = sequences.merge(channel, 1L, Long::sum) & 0xFFFF_FFFFL;
        writer.addMessage(channel, sequence, message.timeNanos(), message.timeNanos(), message.json());
        written++;
    }

    private int channel(Topic topic) throws IOException {
        Integer id = channelIds.get(topic.name());
        if (id != null) {
            return id;
        }
        Integer schema = schemaIds.get(topic.schemaName());
        if (schema == null) {
            schema = writer.addSchema(topic.schemaName(), Topic.SCHEMA_ENCODING, McapWriter.utf8(topic.schema()));
            schemaIds.put(topic.schemaName(), schema);
        }
        int channel = writer.addChannel(topic.name(), Topic.MESSAGE_ENCODING, schema, Map.of());
        channelIds.put(topic.name(), channel);
        return channel;
    }
}
