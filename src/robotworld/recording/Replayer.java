package robotworld.recording;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import robotworld.observe.GroundTruth;
import robotworld.observe.GroundTruthTuples;
import robotworld.observe.ModuleRef;
import robotworld.observe.ReplayMark;
import robotworld.observe.WorldLayout;
import robotworld.recording.mcap.Attachment;
import robotworld.recording.mcap.Channel;
import robotworld.recording.mcap.DataRecord;
import robotworld.recording.mcap.McapFormatException;
import robotworld.recording.mcap.McapReader;
import robotworld.recording.mcap.Message;
import robotworld.recording.mcap.Schema;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Timeout;
import robotworld.safety.SafetyContainers;
import robotworld.telemetry.SafetyTelemetry;
import robotworld.telemetry.TrafficJson;

/**
 * Plays a recording into a space (the contract is in the package documentation). Open it, look at what it holds,
 * then {@link #play} it into a space of its own:
 *
 * <pre>{@code
 * try (Replayer replay = Replayer.open(file)) {
 *     replay.play(space, new Replayer.Options(1.0, false), progress -> ...);
 * }
 * }</pre>
 */
public final class Replayer implements AutoCloseable {

    /** The schema of module traffic messages. */
    static final String TRAFFIC = "rwe.ModuleTraffic";
    /** The schema of ground-truth messages. */
    static final String GROUND_TRUTH = "rwe.GroundTruth";
    /** The schema of the safety layer's stop records. */
    static final String STOP_RECORD = "rwe.StopRecord";

    /**
     * How to play.
     *
     * @param rate how fast: 1 as recorded, 2 twice as fast, 0.5 half as fast
     * @param loop start again at the end, until interrupted
     */
    public record Options(double rate, boolean loop) {
        /** Checks the rate. */
        public Options {
            if (!(rate > 0) || rate > 1000) {
                throw new IllegalArgumentException("the rate must be more than 0 and at most 1000, was " + rate);
            }
        }
    }

    /**
     * How far the replay is.
     *
     * @param played   messages played into the space in this pass
     * @param total    messages there are to play (module traffic and ground truth)
     * @param position recorded time from the first message to the one just played
     * @param length   recorded time from the first to the last message
     * @param pass     1 for the first pass, 2 after the first loop, ...
     * @param skipped  messages that could not be played (malformed), counted
     */
    public record Progress(long played, long total, Duration position, Duration length, int pass, long skipped) {
    }

    private final McapReader reader;
    private final WorldLayout layout;
    private final byte[] worldXml;
    private final long playable;
    private final long firstTime;
    private final long lastTime;

    private Replayer(McapReader reader, WorldLayout layout, byte[] worldXml, long playable, long firstTime,
                     long lastTime) {
        this.reader = reader;
        this.layout = layout;
        this.worldXml = worldXml;
        this.playable = playable;
        this.firstTime = firstTime;
        this.lastTime = lastTime;
    }

    /**
     * Opens a recording and reads what it holds (a full pass over the file).
     *
     * @throws McapFormatException when it is no MCAP file, is damaged, or holds nothing to replay
     */
    public static Replayer open(Path file) throws IOException {
        McapReader reader = McapReader.open(file);
        try {
            WorldLayout recorded = null;
            byte[] worldXml = null;
            Map<Integer, String> schemaNames = new HashMap<>();
            Map<Integer, String> channelSchemas = new HashMap<>();
            Map<String, Map<String, ModuleRef>> modules = new LinkedHashMap<>();
            List<String> robots = new ArrayList<>();
            long playable = 0;
            long first = Long.MAX_VALUE;
            long last = Long.MIN_VALUE;
            McapReader.Cursor cursor = reader.cursor();
            for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
                if (record instanceof Schema schema) {
                    schemaNames.put(schema.id(), schema.name());
                } else if (record instanceof Channel channel) {
                    channelSchemas.put(channel.id(), schemaNames.getOrDefault(channel.schemaId(), ""));
                } else if (record instanceof Attachment attachment) {
                    if (attachment.name().equals(RecordingFormat.LAYOUT_ATTACHMENT) && recorded == null) {
                        recorded = RecordingFormat.layout(TrafficJson.parse(attachment.data()));
                    } else if (attachment.name().equals(RecordingFormat.WORLD_ATTACHMENT) && worldXml == null) {
                        worldXml = attachment.data();
                    }
                } else if (record instanceof Message message) {
                    String schema = channelSchemas.getOrDefault(message.channelId(), "");
                    if (!playable(schema)) {
                        continue;
                    }
                    playable++;
                    first = Math.min(first, message.logTime());
                    last = Math.max(last, message.logTime());
                    if (recorded == null && !schema.equals(STOP_RECORD)) {
                        learn(schema, message, modules, robots);
                    }
                }
            }
            if (playable == 0) {
                throw new McapFormatException(file + " holds no messages to replay (rwe.ModuleTraffic,"
                        + " rwe.GroundTruth or rwe.StopRecord): it was not written by rwe record");
            }
            WorldLayout layout = recorded != null ? recorded : inferred(file, modules, robots);
            return new Replayer(reader, layout, worldXml, playable, first, last);
        } catch (IOException | RuntimeException e) {
            reader.close();
            if (e instanceof IllegalArgumentException) {
                throw new McapFormatException(file + ": " + e.getMessage());
            }
            throw e;
        }
    }

    /** Collects modules and robots from the messages of a file that does not carry its layout. */
    private static void learn(String schema, Message message, Map<String, Map<String, ModuleRef>> modules,
            List<String> robots) throws IOException {
        JsonNode json = TrafficJson.parse(message.data());
        if (schema.equals(TRAFFIC)) {
            ModuleRef module = TrafficJson.traffic(json).module();
            modules.computeIfAbsent(module.participant(), p -> new LinkedHashMap<>()).putIfAbsent(module.name(),
                    module);
        } else {
            String robot = json.path("robot").asText("");
            if (!robot.isEmpty() && !robots.contains(robot)) {
                robots.add(robot);
            }
        }
    }

    private static WorldLayout inferred(Path file, Map<String, Map<String, ModuleRef>> modules, List<String> robots) {
        List<WorldLayout.Participant> participants = new ArrayList<>();
        for (Map.Entry<String, Map<String, ModuleRef>> participant : modules.entrySet()) {
            List<ModuleRef> refs = List.copyOf(participant.getValue().values());
            boolean environment = !robots.contains(participant.getKey())
                    && refs.stream().allMatch(m -> m.moduleClass().startsWith("X10"));
            participants.add(new WorldLayout.Participant(participant.getKey(), environment ? "environment" : "robot",
                    refs));
        }
        for (String robot : robots) {
            if (!modules.containsKey(robot)) {
                participants.add(new WorldLayout.Participant(robot, "robot", List.of()));
            }
        }
        String name = file.getFileName().toString().replaceFirst("\\.mcap$", "");
        return new WorldLayout(name, participants);
    }

    /** The world recorded (from the file's layout attachment, or gathered from its messages). */
    public WorldLayout layout() {
        return layout;
    }

    /** The world's description, if the recording carries it. */
    public Optional<byte[]> worldDescription() {
        return Optional.ofNullable(worldXml == null ? null : worldXml.clone());
    }

    /** Messages there are to play. */
    public long playable() {
        return playable;
    }

    /** Recorded time from the first to the last playable message. */
    public Duration length() {
        return Duration.ofNanos(lastTime - firstTime);
    }

    /** When the first playable message was recorded. */
    public Instant recordedAt() {
        return Instant.ofEpochSecond(0, firstTime);
    }

    /**
     * Plays the recording into {@code space} at the recorded pace (scaled by the rate), once or in a loop, after
     * marking the space as a replay. Returns when done; an interrupt ends it early (and is kept).
     *
     * @param progress told after every message played (on this thread: keep it quick)
     * @throws IOException when the file cannot be read
     */
    public void play(Capi space, Options options, Consumer<Progress> progress) throws IOException {
        Containers containers = prepareContainers(space, options);
        int pass = 1;
        do {
            if (!playOnce(containers, options.rate(), pass, progress)) {
                return;
            }
            pass++;
        } while (options.loop() && !Thread.currentThread().isInterrupted());
    }

    /**
     * Marks {@code space} as replaying this recording and creates the world's containers, so views started now
     * (before {@link #play}) see the mark and an empty world. {@link #play} does it too; doing it twice is harmless.
     */
    public void prepare(Capi space, Options options) {
        prepareContainers(space, options);
    }

    private Containers prepareContainers(Capi space, Options options) {
        Objects.requireNonNull(space, "space");
        new ReplayMark(reader.path().getFileName().toString(), recordedAt(), options.rate()).publish(space);
        Containers containers = new Containers(space);
        for (ModuleRef module : layout.modules()) {
            containers.requests(module);
            containers.answers(module);
        }
        layout.robots().forEach(containers::groundTruth);
        return containers;
    }

    /** One pass; false when interrupted. */
    private boolean playOnce(Containers containers, double rate, int pass, Consumer<Progress> progress)
            throws IOException {
        Map<Integer, String> schemaNames = new HashMap<>();
        Map<Integer, String> channelSchemas = new HashMap<>();
        Map<ModuleRef, Integer> inQueue = new HashMap<>();
        long startNanos = System.nanoTime();
        long played = 0;
        long skipped = 0;
        McapReader.Cursor cursor = reader.cursor();
        for (DataRecord record = cursor.next(); record != null; record = cursor.next()) {
            if (record instanceof Schema schema) {
                schemaNames.put(schema.id(), schema.name());
                continue;
            }
            if (record instanceof Channel channel) {
                channelSchemas.put(channel.id(), schemaNames.getOrDefault(channel.schemaId(), ""));
                continue;
            }
            if (!(record instanceof Message message)) {
                continue;
            }
            String schema = channelSchemas.getOrDefault(message.channelId(), "");
            if (!playable(schema)) {
                continue;
            }
            long due = startNanos + (long) ((message.logTime() - firstTime) / rate);
            if (!waitUntil(due)) {
                return false;
            }
            try {
                JsonNode json = TrafficJson.parse(message.data());
                if (schema.equals(TRAFFIC)) {
                    playTraffic(containers, TrafficJson.traffic(json), json, inQueue);
                } else if (schema.equals(STOP_RECORD)) {
                    containers.space.shift(containers.stops(), Timeout.ofMillis(5_000),
                            SafetyTelemetry.stopRecord(json).toTuple());
                } else {
                    GroundTruth frame = TrafficJson.groundTruth(json, Instant.ofEpochSecond(0, message.logTime()));
                    containers.space.shift(containers.groundTruth(frame.robot()), Timeout.ofMillis(5_000),
                            List.of(Item.keyed(GroundTruthTuples.KEY, GroundTruthTuples.encode(frame))));
                }
                played++;
            } catch (IllegalArgumentException | com.fasterxml.jackson.core.JsonProcessingException e) {
                skipped++;
            }
            progress.accept(new Progress(played, playable, Duration.ofNanos(message.logTime() - firstTime),
                    length(), pass, skipped));
        }
        return true;
    }

    private static boolean playable(String schema) {
        return schema.equals(TRAFFIC) || schema.equals(GROUND_TRUTH) || schema.equals(STOP_RECORD);
    }

    private static void playTraffic(Containers containers, TrafficJson.Traffic traffic, JsonNode json,
            Map<ModuleRef, Integer> inQueue) {
        Capi space = containers.space;
        ModuleRef module = traffic.module();
        Timeout timeout = Timeout.ofMillis(5_000);
        if (traffic.kind().equals("request")) {
            space.write(containers.requests(module), timeout, traffic.call().toTuple());
            inQueue.merge(module, 1, Integer::sum);
        } else {
            space.shift(containers.answers(module), timeout,
                    List.of(Item.keyed(traffic.call().key(), traffic.call().toTuple())));
            if (traffic.call().key().indexOf('#') >= 0 && !json.path("earlier").asBoolean(false)) {
                takeQuietly(space, containers.answers(module), Selector.key(traffic.call().key()));
            }
        }
        // the module took its requests: keep the queue as long as it was when recorded
        int waiting = inQueue.getOrDefault(module, 0);
        int recorded = json.path("queued").canConvertToInt() && json.has("queued") ? json.get("queued").intValue()
                : traffic.kind().equals("request") ? waiting : 0;
        if (waiting > recorded) {
            takeQuietly(space, containers.requests(module), Selector.fifo(waiting - recorded));
            inQueue.put(module, recorded);
        }
    }

    private static void takeQuietly(Capi space, ContainerRef container, Selector selector) {
        try {
            space.take(container, Timeout.TRY_ONCE, selector);
        } catch (SpaceTimeoutException e) {
            // already gone: nothing to take
        }
    }

    private static boolean waitUntil(long dueNanos) {
        while (true) {
            if (Thread.currentThread().isInterrupted()) {
                return false;
            }
            long left = dueNanos - System.nanoTime();
            if (left <= 0) {
                return true;
            }
            LockSupport.parkNanos(Math.min(left, TimeUnit.MILLISECONDS.toNanos(100)));
        }
    }

    @Override
    public void close() throws IOException {
        reader.close();
    }

    /** The containers played into, looked up or created once each (with the runtime's specs). */
    private static final class Containers {
        final Capi space;
        private final Map<String, ContainerRef> byName = new HashMap<>();

        Containers(Capi space) {
            this.space = space;
        }

        ContainerRef requests(ModuleRef module) {
            return get(ContainerSpec.of(Order.FIFO).unbounded().named(module.requestContainer()));
        }

        ContainerRef answers(ModuleRef module) {
            return get(ContainerSpec.of(Order.LIFO).withKeyView().unbounded().named(module.answerContainer()));
        }

        ContainerRef groundTruth(String robot) {
            return get(GroundTruthTuples.containerSpec(robot));
        }

        ContainerRef stops() {
            return get(SafetyContainers.stopsSpec());
        }

        private ContainerRef get(ContainerSpec spec) {
            return byName.computeIfAbsent(spec.name(), name -> space.lookupOrCreateContainer(spec));
        }
    }
}
