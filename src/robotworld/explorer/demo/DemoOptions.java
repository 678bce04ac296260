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
 * @param clusterMembers 0 for one space server in the demo's process; else that many clustered space servers, each
 *                  its own process, of which one is killed (SIGKILL) while the control program runs
 */
public record DemoOptions(Duration run, Viewpoint viewpoint, Path out, boolean console, Path home,
                          boolean killControl, Path record, int clusterMembers) {

    /** The demo without the kill and without a recording. */
    public DemoOptions(Duration run, Viewpoint viewpoint, Path out, boolean console, Path home) {
        this(run, viewpoint, out, console, home, false, null, 0);
    }

    /** The demo, with or without the kill, without a recording. */
    public DemoOptions(Duration run, Viewpoint viewpoint, Path out, boolean console, Path home, boolean killControl) {
        this(run, viewpoint, out, console, home, killControl, null, 0);
    }

    /** The same, recording into {@code file} (null: none). */
    public DemoOptions recording(Path file) {
        return new DemoOptions(run, viewpoint, out, console, home, killControl, file, clusterMembers);
    }

    /** The same, on a clustered space of {@code members} server processes (0: one server in this process). */
    public DemoOptions clustered(int members) {
        return new DemoOptions(run, viewpoint, out, console, home, killControl, record, members);
    }

    public DemoOptions {
        Objects.requireNonNull(run, "run");
        Objects.requireNonNull(viewpoint, "viewpoint");
        Objects.requireNonNull(out, "out");
        Objects.requireNonNull(home, "home");
        if (run.isNegative() || run.isZero() || run.compareTo(Duration.ofMinutes(30)) > 0) {
            throw new IllegalArgumentException("the run must last more than 0 s and at most 30 min, was " + run);
        }
        if (clusterMembers != 0 && (clusterMembers < 3 || clusterMembers > 5)) {
            throw new IllegalArgumentException("a clustered demo runs 3 to 5 members (one is killed, the others"
                    + " must stay a majority), not " + clusterMembers);
        }
    }

    /** rwe.home, else the working directory. */
    public static Path defaultHome() {
        return Path.of(System.getProperty("rwe.home", ".")).toAbsolutePath().normalize();
    }
}
