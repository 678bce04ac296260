package robotworld.bus.explore;

import java.time.Duration;
import java.util.Arrays;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.sim.robot.LineTiming;
import robotworld.sim.robot.SimRobotConfig;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;

/**
 * Exploration soak ({@code ./antw soak-explore}): full 1..247 scans at the default timing a user gets, counting for
 * every scan the modules found, reported and lost (neither). Two runs:
 * <ol>
 * <li>50 scans of the example robot whose modules answer late and trickle (12 ms, then a byte per ms), corrupt a
 *     fifth of their replies, answer 30 ms late, and trickle a byte every 2 ms;</li>
 * <li>10 scans of the example robot talking at 9600 baud (real timing) explored at 115200.</li>
 * </ol>
 * Exits with 1 if any scan lost a module. Knobs: {@code -Dsoak.scans=50}, {@code -Dsoak.mismatchScans=10}.
 */
public final class ExplorationSoak {

    private ExplorationSoak() {
    }

    public static void main(String[] args) throws Exception {
        int scans = Integer.getInteger("soak.scans", 50);
        int mismatchScans = Integer.getInteger("soak.mismatchScans", 10);
        SimRobotConfig example = SimRobotConfigReader.read(ProjectFiles.resolve("docs/examples/simulated-robot.sim"));
        System.out.printf("Exploration soak, Java %s, %d CPUs%n%n", System.getProperty("java.version"),
                Runtime.getRuntime().availableProcessors());
        int lost = run("troubled modules (late+trickle, 20 % CRC errors, 30 ms late, 2 ms trickle), 115200 baud",
                example.withTiming(LineTiming.FAST), true, scans);
        lost += run("modules at 9600 baud (real timing) explored at 115200", example.withTiming(LineTiming.REAL)
                .withBaud(9600), false, mismatchScans);
        System.out.println(lost == 0 ? "PASS: every module found or reported in every scan"
                : "FAIL: " + lost + " modules lost");
        System.exit(lost == 0 ? 0 : 1);
    }

    private static int run(String label, SimRobotConfig config, boolean troubled, int scans) throws Exception {
        if (scans <= 0) {
            return 0; // this part was left out (-Dsoak.scans=0 or -Dsoak.mismatchScans=0)
        }
        System.out.println(label + ", " + scans + " full scans");
        int lost = 0;
        int[] found = new int[scans];
        double[] seconds = new double[scans];
        int hinted = 0;
        try (SimulatedRobot robot = SimulatedRobot.create(config)) {
            if (troubled) {
                robot.faults(1).replyDelay(Duration.ofMillis(12)).trickle(Duration.ofMillis(1));
                robot.faults(2).crcErrorRate(0.2);
                robot.faults(3).replyDelay(Duration.ofMillis(30));
                robot.faults(4).trickle(Duration.ofMillis(2));
            }
            String port = robot.serve("tcp://127.0.0.1:0");
            Set<Integer> modules = robot.simulation().modules().keySet();
            for (int scan = 0; scan < scans; scan++) {
                try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(115_200), BusTiming.defaults())) {
                    ExplorationResult result = new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve(
                            "ModuleDescriptions"))).explore("Soak", new ExplorationListener() { });
                    Set<Integer> seen = new TreeSet<>();
                    result.modules().forEach(m -> seen.add(m.address()));
                    result.problems().forEach(p -> seen.add(p.address()));
                    Set<Integer> missing = new TreeSet<>(modules);
                    missing.removeAll(seen);
                    lost += missing.size();
                    found[scan] = result.modules().size();
                    seconds[scan] = result.elapsed().toNanos() / 1e9;
                    hinted += result.baudMismatch() ? 1 : 0;
                    System.out.printf(Locale.ROOT, "  scan %2d: %d found, %d reported%s, %.1f s%s%n", scan + 1,
                            result.modules().size(), result.problems().size(), missing.isEmpty() ? ""
                                    : ", LOST " + missing, seconds[scan], result.problems().isEmpty() ? ""
                                            : "  " + result.problems());
                }
            }
        }
        Arrays.sort(seconds);
        long allFound = Arrays.stream(found).filter(n -> n == 4).count();
        System.out.printf(Locale.ROOT, "  => %d of %d scans found all 4 modules; lost %d; baud-rate hint in %d scans;"
                + " scan time median %.1f s (min %.1f, max %.1f)%n%n", allFound, scans, lost, hinted,
                seconds[scans / 2], seconds[0], seconds[scans - 1]);
        return lost;
    }
}
