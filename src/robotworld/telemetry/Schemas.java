package robotworld.telemetry;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/** The JSON Schemas of every topic, read from this package's {@code schemas/} folder. */
public final class Schemas {

    /** Every schema name there is. */
    public static final List<String> NAMES = List.of("rwe.ModuleTraffic", "rwe.Liveness", "rwe.ActuatorStopped",
            "rwe.Gap", "rwe.StopRecord", "rwe.Heartbeat", "rwe.GroundTruth", "foxglove.SceneUpdate", "foxglove.FrameTransforms", "foxglove.PoseInFrame",
            "foxglove.LaserScan");

    private static final Map<String, String> TEXTS = new ConcurrentHashMap<>();

    private Schemas() {
    }

    /**
     * The schema's JSON text.
     *
     * @throws IllegalArgumentException for a name not in {@link #NAMES}
     */
    public static String text(String name) {
        if (!NAMES.contains(name)) {
            throw new IllegalArgumentException("no schema named " + name + "; there are " + NAMES);
        }
        return TEXTS.computeIfAbsent(name, Schemas::load);
    }

    private static String load(String name) {
        try (InputStream in = Schemas.class.getResourceAsStream("schemas/" + name + ".json")) {
            if (in == null) {
                throw new IllegalStateException("the schema " + name + " is missing from the program's classes");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
