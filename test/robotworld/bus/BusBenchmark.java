package robotworld.bus;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import robotworld.testsupport.TcpEcho;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.bus.modbus.DeviceIdentification;
import robotworld.bus.modbus.RtuTiming;
import robotworld.sim.robot.LineTiming;
import robotworld.sim.robot.SimRobotConfig;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;

/**
 * Module bus benchmark ({@code ./antw bench-bus}), each figure a median over several runs, set against a baseline
 * measured or computed in the same run:
 * <ol>
 * <li>a full 1..247 scan of the example robot (4 modules) at 115200 baud with real timing, over {@code tcp://}
 *     and through a socat pty pair, against the protocol's own floor: the wire time of every frame, the
 *     3.5-character silences and the scan timeout of each absent address;</li>
 * <li>one bumper read round trip at fast timing over {@code tcp://}, against a plain TCP loopback round trip of
 *     the same frame sizes.</li>
 * </ol>
 */
public final class BusBenchmark {

    private static final int SCAN_RUNS = 5;
    private static final int PTY_SCAN_RUNS = 3;
    private static final int ROUND_TRIP_RUNS = 7;
    private static final int CALLS_PER_RUN = 2000;

    private BusBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        System.out.printf("Module bus benchmark, %s, Java %s, %d CPUs%n%n", System.getProperty("os.name"),
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors());
        SimRobotConfig example = SimRobotConfigReader.read(ProjectFiles.resolve("docs/examples/simulated-robot.sim"));
        scan(example.withTiming(LineTiming.REAL), false, SCAN_RUNS);
        scan(example.withTiming(LineTiming.REAL), true, PTY_SCAN_RUNS);
        roundTrip(example.withTiming(LineTiming.FAST), BusTiming.defaults(), "default frame gap (3.5 chars)");
        roundTrip(example.withTiming(LineTiming.FAST), BusTiming.defaults().withFrameGap(Duration.ZERO),
                "frame gap 0 (simulator link)");
    }

    private static void scan(SimRobotConfig config, boolean overPty, int runs) throws Exception {
        SocatPty pty = overPty ? SocatPty.start() : null;
        try (SimulatedRobot robot = SimulatedRobot.create(config)) {
            String port = overPty ? pty.b().toString() : robot.serve("tcp://127.0.0.1:0");
            if (overPty) {
                robot.serve(pty.a().toString());
            }
            SerialSettings settings = SerialSettings.eightNoneOne(config.baud());
            try (RS485Bus bus = new RS485Bus(port, settings, BusTiming.defaults())) {
                ModuleCatalog catalog = new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions"));
                double floor = scanFloorMillis(bus, settings);
                new RobotExplorer(bus, catalog).explore("Warmup", new ExplorationListener() { });
                double[] millis = new double[runs];
                ExplorationResult last = null;
                for (int i = 0; i < runs; i++) {
                    long start = System.nanoTime();
                    last = new RobotExplorer(bus, catalog).explore("Bench", new ExplorationListener() { });
                    millis[i] = (System.nanoTime() - start) / 1e6;
                }
                double median = median(millis);
                System.out.printf(Locale.ROOT, "full scan 1..247, %d modules, %d baud real timing, over %s%n",
                        last.modules().size(), config.baud(), overPty ? "a socat pty pair (jSerialComm)" : "tcp://");
                System.out.printf(Locale.ROOT, "  runs (ms): %s%n", rounded(millis));
                System.out.printf(Locale.ROOT, "  median %.0f ms (target <= 5000 ms); scan timeout %.2f ms per absent "
                        + "address%n", median, bus.scanReplyTimeout().toNanos() / 1e6);
                System.out.printf(Locale.ROOT, "  protocol floor %.0f ms (frames on the wire + silences + scan "
                        + "timeouts); ratio %.2f%n", floor, median / floor);
                System.out.printf(Locale.ROOT, "  problems %d, stray frames %d%n%n", last.problems().size(),
                        last.statistics().strayFrames());
            }
        } finally {
            if (pty != null) {
                pty.close();
            }
        }
    }

    /**
     * The least time a scan can take at this line speed with this scan timeout: every request on the wire, then
     * for an absent address the scan timeout; for a module its three replies (identification, status, echo), each
     * after a 3.5-character silence and followed by one before the next request.
     */
    private static double scanFloorMillis(RS485Bus bus, SerialSettings settings) {
        RtuTiming rtu = RtuTiming.of(settings.baudRate(), settings.characterTimeNanos());
        long nanos = 0;
        for (int address = 1; address <= 247; address++) {
            nanos += rtu.wireNanos(7); // identification request
            DeviceIdentification identity;
            try {
                identity = bus.probe(address);
            } catch (BusException absent) {
                nanos += bus.scanReplyTimeout().toNanos();
                continue;
            }
            int identityReply = 3 + 7;
            for (String value : identity.objects().values()) {
                identityReply += 2 + value.length();
            }
            int statusReply = 3 + 4 + identity.productCode().length();
            nanos += rtu.t35Nanos() + rtu.wireNanos(identityReply) + rtu.t35Nanos();
            nanos += rtu.wireNanos(4) + rtu.t35Nanos() + rtu.wireNanos(statusReply) + rtu.t35Nanos();
            nanos += rtu.wireNanos(8) + rtu.t35Nanos() + rtu.wireNanos(8) + rtu.t35Nanos();
        }
        return nanos / 1e6;
    }

    private static void roundTrip(SimRobotConfig config, BusTiming timing, String label) throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.create(config);
                RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"),
                        SerialSettings.eightNoneOne(config.baud()), timing);
                TcpEcho echo = new TcpEcho(8, 6)) {
            BumperModuleProxy bumper = new BumperModuleProxy(bus, 2);
            double[] p50 = new double[ROUND_TRIP_RUNS];
            double[] p99 = new double[ROUND_TRIP_RUNS];
            double[] tcp = new double[ROUND_TRIP_RUNS];
            for (int i = 0; i < CALLS_PER_RUN; i++) {
                bumper.getAllBumper();
                echo.roundTrip();
            }
            for (int run = 0; run < ROUND_TRIP_RUNS; run++) {
                long[] calls = new long[CALLS_PER_RUN];
                long[] echoes = new long[CALLS_PER_RUN];
                for (int i = 0; i < CALLS_PER_RUN; i++) {
                    long start = System.nanoTime();
                    bumper.getAllBumper();
                    calls[i] = System.nanoTime() - start;
                    start = System.nanoTime();
                    echo.roundTrip();
                    echoes[i] = System.nanoTime() - start;
                }
                Arrays.sort(calls);
                Arrays.sort(echoes);
                p50[run] = calls[CALLS_PER_RUN / 2] / 1e3;
                p99[run] = calls[CALLS_PER_RUN * 99 / 100] / 1e3;
                tcp[run] = echoes[CALLS_PER_RUN / 2] / 1e3;
            }
            double medianP50 = median(p50);
            double medianTcp = median(tcp);
            System.out.printf(Locale.ROOT, "bumper read round trip (getAllBumper), fast timing, tcp://, %s%n", label);
            System.out.printf(Locale.ROOT, "  p50 %.1f us, p99 %.1f us (medians of %d runs x %d calls)%n", medianP50,
                    median(p99), ROUND_TRIP_RUNS, CALLS_PER_RUN);
            System.out.printf(Locale.ROOT, "  baseline: TCP loopback round trip of the same frame sizes p50 %.1f us; "
                    + "ratio %.1f%n%n", medianTcp, medianP50 / medianTcp);
        }
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int middle = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2;
    }

    private static List<Long> rounded(double[] values) {
        List<Long> result = new ArrayList<>();
        for (double value : values) {
            result.add(Math.round(value));
        }
        return result;
    }
}
