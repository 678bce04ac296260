package robotworld.recording.mcap;

import java.nio.charset.StandardCharsets;
import java.util.Objects;

/**
 * A schema record: how messages of channels that refer to it are laid out.
 *
 * @param id       1..65535, unique in the file
 * @param name     e.g. {@code rwe.ModuleTraffic}
 * @param encoding e.g. {@code jsonschema}; empty when there is no schema
 * @param data     the schema itself
 */
public record Schema(int id, String name, String encoding, byte[] data)
        implements DataRecord {

    /** Checks the fields. */
    public Schema {
        if (id < 1 || id > 0xFFFF) {
            throw new IllegalArgumentException("a schema id is 1..65535, was " + id);
        }
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(encoding, "encoding");
        Objects.requireNonNull(data, "data");
    }

    /** The schema as text (JSON Schemas are UTF-8 text). */
    public String text() {
        return new String(data, StandardCharsets.UTF_8);
    }
}
