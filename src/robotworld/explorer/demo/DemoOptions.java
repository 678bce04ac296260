package robotworld.explorer.demo;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;

/**
 * How the demo runs.
 *
 * @param run       how long the control program runs
 * @param viewpoint which main class gets the control program
 * @param out       where the descriptions and generated projects go
 * @param console   console monitor even when a display is available
 * @param home      the RobotWorldExplorer home (ModuleDescriptions/, docs/examples/)
 * @param killControl kill the control program (SIGKILL) while the robot drives, and show the robot stopping
 * @param record    an MCAP file to record the world's traffic into, or null for none
 */
public record DemoOptions(Duration run, Viewpoint viewpoint, Path out, boolean console, Path home,
                          boolean killControl, Path record) {

    /** The demo without the kill and without a recording. */
    public DemoOptions(Duration run, Viewpoint viewpoint, Path out, boolean console, Path home) {
        this(run, viewpoint, out, console, home, false, null);
    }

    /** The demo, with or without the kill, without a recording. */
    public DemoOptions(Duration run, Viewpoint viewpoint, Path out, boolean console, Path home, boolean killControl) {
        this(run, viewpoint, out, console, home, killControl, null);
    }

    /** The same, recording into {@code file} (null: none). */
    public DemoOptions recording(Path file) {
        return new DemoOptions(run, viewpoint, out, console, home, killControl, file);
    }

    public DemoOptions {
        Objects.requireNonNull(run, "run");
        Objects.requireNonNull(viewpoint, "viewpoint");
        Objects.requireNonNull(out, "out");
        Objects.requireNonNull(home, "home");
        if (run.isNegative() || run.isZero() || run.compareTo(Duration.ofMinutes(30)) > 0) {
            throw new IllegalArgumentException("the run must last more than 0 s and at most 30 min, was " + run);
        }
    }

    /** rwe.home, else the working directory. */
    public static Path defaultHome() {
        return Path.of(System.getProperty("rwe.home", ".")).toAbsolutePath().normalize();
    }
}
