package robotworld.telemetry;

import java.nio.charset.StandardCharsets;
import java.util.Objects;

/**
 * One JSON message on a topic.
 *
 * @param topic     where it goes
 * @param timeNanos when it happened, ns since the epoch
 * @param json      the message, UTF-8 JSON
 */
public record TelemetryMessage(Topic topic, long timeNanos, byte[] json) {

    /** Checks the fields. */
    public TelemetryMessage {
        Objects.requireNonNull(topic, "topic");
        Objects.requireNonNull(json, "json");
    }

    /** The message as text. */
    public String text() {
        return new String(json, StandardCharsets.UTF_8);
    }
}
