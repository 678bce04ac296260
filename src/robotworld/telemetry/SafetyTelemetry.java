package robotworld.telemetry;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.safety.Heartbeat;
import robotworld.safety.SafetyContainers;
import robotworld.safety.StopCause;
import robotworld.safety.StopRecord;
import robotworld.safety.StopWatcher;
import robotworld.space.Capi;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.SpaceException;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/**
 * The safety layer's traffic of a space as messages: every stop record ({@value #STOP_RECORDS_TOPIC}) and every
 * heartbeat ({@value #HEARTBEATS_TOPIC}), handed to a sink on the space's delivery threads. These are world-wide
 * containers, not a module's, so they are watched here beside the {@link robotworld.observe.WorldTap}. A
 * subscription that overflowed is renewed (records between are missed, and a gap message says so).
 */
public final class SafetyTelemetry implements AutoCloseable {

    static final String STOP_RECORDS_TOPIC = "/rwe/stop_records";
    static final String HEARTBEATS_TOPIC = "/rwe/heartbeats";
    private static final Logger LOG = LoggerFactory.getLogger(SafetyTelemetry.class);
    private static final Set<Operation> PUBLISHING = Set.of(Operation.WRITE, Operation.SHIFT);

    private final Capi space;
    private final Consumer<TelemetryMessage> sink;
    private StopWatcher stops;
    private Subscription heartbeats;
    private boolean closed;

    private SafetyTelemetry(Capi space, Consumer<TelemetryMessage> sink) {
        this.space = space;
        this.sink = sink;
    }

    /**
     * Starts watching the stop records and heartbeats of {@code space}.
     *
     * @throws SpaceException when the space cannot be reached
     */
    public static SafetyTelemetry start(Capi space, Consumer<TelemetryMessage> sink) {
        SafetyTelemetry telemetry = new SafetyTelemetry(Objects.requireNonNull(space, "space"),
                Objects.requireNonNull(sink, "sink"));
        telemetry.stops = StopWatcher.start(space, record -> telemetry.send(Topics.STOP_RECORDS, record.at(),
                stopRecord(record)));
        telemetry.watchHeartbeats();
        return telemetry;
    }

    private synchronized void watchHeartbeats() {
        if (closed) {
            return;
        }
        heartbeats = space.subscribe(SafetyContainers.liveness(space), PUBLISHING, NotificationMode.INFINITE,
                Timeout.INFINITE, new NotificationListener() {
                    @Override
                    public void onNotification(Notification notification) {
                        for (Entry entry : notification.entries()) {
                            try {
                                Heartbeat beat = Heartbeat.parse(entry);
                                send(Topics.HEARTBEATS, Instant.now(), heartbeat(beat));
                            } catch (IllegalArgumentException e) {
                                LOG.debug("not a heartbeat: {}", entry);
                            }
                        }
                    }

                    @Override
                    public void onEnd(SubscriptionEnd reason) {
                        if (reason == SubscriptionEnd.OVERFLOWED || reason == SubscriptionEnd.CONTAINER_DESTROYED) {
                            ObjectNode gap = TrafficJson.MAPPER.createObjectNode();
                            gap.putNull("participant");
                            gap.putNull("module");
                            gap.put("missed", -1);
                            gap.put("why", SafetyContainers.LIVENESS + ": the space dropped notifications; watching"
                                    + " again");
                            gap.put("ended", false);
                            send(Topics.GAPS, Instant.now(), gap);
                            try {
                                watchHeartbeats();
                            } catch (SpaceException e) {
                                LOG.debug("cannot watch the heartbeats again: {}", e.getMessage());
                            }
                        }
                    }
                });
    }

    private void send(Topic topic, Instant at, JsonNode json) {
        sink.accept(new TelemetryMessage(topic, WorldTelemetry.nanos(at), TrafficJson.bytes(json)));
    }

    /** A stop record as {@code rwe.StopRecord}. */
    public static ObjectNode stopRecord(StopRecord record) {
        ObjectNode node = TrafficJson.MAPPER.createObjectNode();
        node.put("at_millis", record.at().toEpochMilli());
        node.put("participant", record.participant());
        node.put("module", record.module());
        node.put("cause", record.cause().wireName());
        node.put("reason", record.reason());
        node.put("action", record.action());
        node.put("stopped_by", record.stoppedBy());
        node.put("commander", record.commander());
        node.put("request", record.request());
        return node;
    }

    /**
     * Reads an {@code rwe.StopRecord} message.
     *
     * @throws IllegalArgumentException when it is not one
     */
    public static StopRecord stopRecord(JsonNode node) {
        if (!node.path("at_millis").canConvertToLong() || !node.path("cause").isTextual()) {
            throw new IllegalArgumentException("not a stop record: " + node);
        }
        return new StopRecord(Instant.ofEpochMilli(node.get("at_millis").longValue()),
                node.path("participant").asText(""), node.path("module").asText(""),
                StopCause.ofWireName(node.get("cause").asText()), node.path("reason").asText(""),
                node.path("action").asText(""), node.path("stopped_by").asText(""),
                node.path("commander").asText(""), node.path("request").asText(""));
    }

    /** A heartbeat as {@code rwe.Heartbeat}. */
    public static ObjectNode heartbeat(Heartbeat beat) {
        ObjectNode node = TrafficJson.MAPPER.createObjectNode();
        node.put("id", beat.id());
        node.put("host", beat.host());
        ArrayNode serves = node.putArray("serves");
        beat.serves().forEach(module -> serves.add(module.toString()));
        node.put("state", beat.ended() ? Heartbeat.ENDED : Heartbeat.ALIVE);
        node.put("sequence", beat.sequence());
        node.put("period_ms", beat.periodMillis());
        node.put("sent_at_millis", beat.sentAtMillis());
        return node;
    }

    @Override
    public synchronized void close() {
        closed = true;
        if (stops != null) {
            stops.close();
        }
        if (heartbeats != null) {
            try {
                heartbeats.cancel();
            } catch (RuntimeException e) {
                LOG.debug("cancelling the heartbeat subscription: {}", e.getMessage());
            }
        }
    }
}
