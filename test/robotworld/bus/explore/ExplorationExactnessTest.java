package robotworld.bus.explore;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.sim.robot.LineTiming;
import robotworld.sim.robot.SimRobotConfig;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;

/**
 * Exploration finds every module that answers at all, or reports it: modules that answer after the scan timeout
 * and trickle their bytes, modules that corrupt a share of their replies, and modules at another baud rate, which
 * also get a hint and are found by {@code --baud auto}. Inter-byte timeouts are generous, so a busy machine cannot
 * cut a trickling reply; the soak target ({@code ./antw soak-explore}) runs the same at default timing, many times.
 */
class ExplorationExactnessTest {

    /** Patient inside a reply, default elsewhere. */
    private static final BusTiming PATIENT = new BusTiming(Duration.ofMillis(100), 3, Duration.ofMillis(300),
            Duration.ofMillis(8), BusTiming.AUTO_FRAME_GAP, Duration.ofSeconds(5));

    private static SimRobotConfig example() throws Exception {
        return SimRobotConfigReader.read(ProjectFiles.resolve("docs/examples/simulated-robot.sim"));
    }

    private static RobotExplorer explorer(RS485Bus bus) {
        return new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions"))).addresses(1, 12);
    }

    private static Set<Integer> foundOrReported(ExplorationResult result) {
        Set<Integer> addresses = new TreeSet<>();
        result.modules().forEach(m -> addresses.add(m.address()));
        result.problems().forEach(p -> addresses.add(p.address()));
        return addresses;
    }

    @Test
    void modulesThatAnswerLateAndTrickleAreAllFound() throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.create(example().withTiming(LineTiming.FAST))) {
            for (int address = 1; address <= 4; address++) {
                robot.faults(address).replyDelay(Duration.ofMillis(12)).trickle(Duration.ofMillis(1));
            }
            String port = robot.serve("tcp://127.0.0.1:0");
            for (int run = 0; run < 2; run++) {
                try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(115_200), PATIENT)) {
                    ExplorationResult result = explorer(bus).explore("Late", new ExplorationListener() { });
                    // found, or (on a machine so busy that even the patient retries missed) reported, never lost
                    assertEquals(Set.of(1, 2, 3, 4), foundOrReported(result), "run " + run + ": " + result.problems());
                }
            }
        }
    }

    @Test
    void twoSlowModulesAmongCleanOnesAreNoBaudRateMismatch() throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.create(example().withTiming(LineTiming.FAST))) {
            robot.faults(1).replyDelay(Duration.ofMillis(12)).trickle(Duration.ofMillis(1));
            robot.faults(4).trickle(Duration.ofMillis(2));
            try (RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                    PATIENT)) {
                ExplorationResult result = explorer(bus).explore("Trickling", new ExplorationListener() { });
                assertEquals(Set.of(1, 2, 3, 4), foundOrReported(result), result.problems().toString());
                // the trickling modules are slow (a byte per 1-2 ms), the bumper and servo answer at the line's pace
                assertFalse(result.baudMismatch(), result.notes().toString());
                assertTrue(result.suggestedBaud().isEmpty());
                assertTrue(result.notes().stream().noneMatch(n -> n.contains("baud")), result.notes().toString());
            }
        }
    }

    @Test
    void modulesThatCorruptAShareOfTheirRepliesAreFoundOrReported() throws Exception {
        SimRobotConfig config = example().withTiming(LineTiming.FAST);
        try (SimulatedRobot robot = SimulatedRobot.create(config)) {
            for (int address = 1; address <= 4; address++) {
                robot.faults(address).crcErrorRate(0.3);
            }
            try (RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                    PATIENT)) {
                List<String> runs = new ArrayList<>();
                for (int run = 0; run < 3; run++) {
                    ExplorationResult result = explorer(bus).explore("Noisy", new ExplorationListener() { });
                    assertEquals(Set.of(1, 2, 3, 4), foundOrReported(result), "run " + run + ": " + result.problems());
                    runs.add(result.modules().size() + " found");
                }
            }
        }
    }

    @Test
    void modulesAtAnotherBaudRateAreFoundWithAHintAndAutoFindsTheirRate() throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.create(example().withTiming(LineTiming.REAL).withBaud(9600))) {
            String port = robot.serve("tcp://127.0.0.1:0");
            try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(115_200), PATIENT)) {
                ExplorationResult result = explorer(bus).explore("Slow", new ExplorationListener() { });
                assertEquals(Set.of(1, 2, 3, 4), foundOrReported(result), result.problems().toString());
                assertTrue(result.baudMismatch());
                assertEquals(9600, result.suggestedBaud().orElse(0), result.notes().toString());
                assertTrue(result.notes().stream().anyMatch(n -> n.contains("--baud 9600")), result.notes().toString());
            }
            List<String> said = new ArrayList<>();
            BaudRateSearch.Outcome outcome = BaudRateSearch.explore(
                    rate -> new RS485Bus(port, SerialSettings.eightNoneOne(rate), PATIENT),
                    ExplorationExactnessTest::explorer, "Slow", new ExplorationListener() { }, said::add);
            assertEquals(9600, outcome.baud(), said.toString());
            assertEquals(List.of(115_200, 9600), outcome.tried());
            assertEquals(Set.of(1, 2, 3, 4), foundOrReported(outcome.result()));
        }
    }
}
