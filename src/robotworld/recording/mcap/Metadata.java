package robotworld.recording.mcap;

import java.util.Map;
import java.util.Objects;

/**
 * A metadata record: named key/value pairs about the whole recording.
 *
 * @param name   e.g. {@code rwe.recording}
 * @param values the pairs
 */
public record Metadata(String name, Map<String, String> values)
        implements DataRecord {

    /** Copies the values. */
    public Metadata {
        Objects.requireNonNull(name, "name");
        values = Map.copyOf(values);
    }
}
