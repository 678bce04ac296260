package robotworld.telemetry;

import java.util.Objects;

/**
 * A named stream of JSON messages with one JSON Schema.
 *
 * @param name       e.g. {@code /CaterpillarRobot/Motor-Controller}
 * @param schemaName e.g. {@code rwe.ModuleTraffic}
 */
public record Topic(String name, String schemaName) {

    /** How every message is encoded. */
    public static final String MESSAGE_ENCODING = "json";
    /** How every schema is encoded. */
    public static final String SCHEMA_ENCODING = "jsonschema";

    /** Checks the fields; the schema must be one of {@link Schemas}. */
    public Topic {
        Objects.requireNonNull(name, "name");
        Schemas.text(schemaName);
    }

    /** The JSON Schema text. */
    public String schema() {
        return Schemas.text(schemaName);
    }
}
