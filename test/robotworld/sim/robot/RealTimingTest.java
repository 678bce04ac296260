package robotworld.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.FoundModule;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.testsupport.ProjectFiles;

/** With real timing the simulator paces replies at the baud rate; exploration still works within its timeouts. */
class RealTimingTest {

    @Test
    void repliesTakeTheirWireTimeAndExplorationStillFindsEveryModule() throws Exception {
        SimRobotConfig config = SimRobotConfigReader.read(ProjectFiles.resolve("docs/examples/simulated-robot.sim"))
                .withTiming(LineTiming.REAL).withBaud(19_200);
        try (SimulatedRobot robot = SimulatedRobot.create(config);
                RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(19_200),
                        BusTiming.defaults())) {
            BumperModuleProxy bumper = new BumperModuleProxy(bus, 2);
            bumper.getAllBumper();
            // at 19200 baud a character takes 521 us: request 8 + silence 3.5 + reply 6 characters = 9.1 ms
            // the fastest of 5 to 20 tries: on a busy machine some round trips are held up, and one unhindered
            // round trip is enough to show the pacing is not much slower than the line
            long fastest = Long.MAX_VALUE;
            for (int i = 0; i < 5 || (i < 20 && fastest >= 40_000_000); i++) {
                long start = System.nanoTime();
                assertEquals(0, bumper.getAllBumper());
                fastest = Math.min(fastest, System.nanoTime() - start);
            }
            assertTrue(fastest >= 9_000_000, "a round trip cannot beat the line: " + fastest / 1e6 + " ms");
            assertTrue(fastest < 40_000_000, "but it is not much slower either: " + fastest / 1e6 + " ms");

        }
        // exploration frames paced replies right; its probes get a scan allowance that a busy machine cannot eat
        // (the default 8 ms is met by a quiet machine; a late reply is another matter, tested in RobotExplorerTest)
        try (SimulatedRobot robot = SimulatedRobot.create(config);
                RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(19_200),
                        BusTiming.defaults().withScanAllowance(Duration.ofMillis(500)))) {
            ExplorationResult result = new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve(
                    "ModuleDescriptions"))).addresses(1, 8).explore("RealTime", new ExplorationListener() { });
            assertEquals(List.of(1, 2, 3, 4), result.modules().stream().map(FoundModule::address).toList());
            assertEquals(List.of(), result.problems());
        }
    }
}
