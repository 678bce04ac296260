package robotworld.explorer.monitor.gui;

import java.awt.Rectangle;
import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Remembers the monitor window's layout between runs (bounds, maximized, the dividers, the selected tab) in a small
 * properties file: {@code rwe.monitor.layout} if set (a file, or {@code none} to remember nothing), else
 * {@code $XDG_CONFIG_HOME/robotworld/monitor-layout.properties} ({@code ~/.config/...}). A missing or damaged file
 * means the defaults; a file that cannot be written is logged, never an error.
 */
public final class LayoutMemory {

    private static final Logger LOG = LoggerFactory.getLogger(LayoutMemory.class);

    private final Path file;
    private final Properties values = new Properties();

    private LayoutMemory(Path file) {
        this.file = file;
        if (file != null && Files.isRegularFile(file)) {
            try (Reader reader = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
                values.load(reader);
            } catch (IOException | IllegalArgumentException e) {
                LOG.debug("ignoring the monitor layout in {}: {}", file, e.getMessage());
            }
        }
    }

    /** The memory in {@code file}, or none when null. */
    public static LayoutMemory in(Path file) {
        return new LayoutMemory(file);
    }

    /** A memory that forgets (tests, embedding). */
    public static LayoutMemory none() {
        return new LayoutMemory(null);
    }

    /** The memory the user's settings name (see the class comment). */
    public static LayoutMemory fromSettings() {
        String configured = System.getProperty("rwe.monitor.layout");
        if (configured != null && !configured.isBlank()) {
            return configured.strip().equals("none") ? none() : in(Path.of(configured.strip()));
        }
        String xdg = System.getenv("XDG_CONFIG_HOME");
        Path base = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(System.getProperty("user.home"), ".config");
        return in(base.resolve("robotworld").resolve("monitor-layout.properties"));
    }

    /** The file, or null when nothing is remembered. */
    public Path file() {
        return file;
    }

    /** The remembered window bounds, or null. */
    public Rectangle bounds() {
        try {
            String[] parts = values.getProperty("window.bounds", "").split(",");
            if (parts.length != 4) {
                return null;
            }
            Rectangle bounds = new Rectangle(Integer.parseInt(parts[0].strip()), Integer.parseInt(parts[1].strip()),
                    Integer.parseInt(parts[2].strip()), Integer.parseInt(parts[3].strip()));
            return bounds.width >= 200 && bounds.height >= 150 ? bounds : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** A remembered whole number, or {@code fallback}. */
    public int number(String key, int fallback) {
        try {
            return Integer.parseInt(values.getProperty(key, "").strip());
        } catch (NumberFormatException e) {
            return fallback;
        }
    }

    /** A remembered flag. */
    public boolean flag(String key) {
        return Boolean.parseBoolean(values.getProperty(key));
    }

    /** A remembered text, or {@code fallback}. */
    public String text(String key, String fallback) {
        return values.getProperty(key, fallback);
    }

    /** Sets the bounds to remember. */
    public LayoutMemory bounds(Rectangle bounds) {
        values.setProperty("window.bounds", bounds.x + "," + bounds.y + "," + bounds.width + "," + bounds.height);
        return this;
    }

    /** Sets a value to remember. */
    public LayoutMemory put(String key, Object value) {
        values.setProperty(key, String.valueOf(value));
        return this;
    }

    /** Writes what is remembered to the file (nothing when there is none). */
    public void save() {
        if (file == null) {
            return;
        }
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            try (Writer writer = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
                values.store(writer, "RobotWorldExplorer monitor window layout");
            }
        } catch (IOException e) {
            LOG.warn("cannot remember the monitor layout in {}: {}", file, e.getMessage());
        }
    }
}
