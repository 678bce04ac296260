package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.FoundModule;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.testsupport.ProjectFiles;

/**
 * An RS-485 adapter that echoes every request (half-duplex, no echo suppression), simulated by the line: detected
 * and cancelled by default, cancelled when asked, and named with the fix when cancellation is off.
 */
class EchoCancellationTest {

    private static RobotExplorer explorer(RS485Bus bus) {
        return new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions"))).addresses(1, 8);
    }

    @Test
    void byDefaultTheEchoIsDetectedAndExplorationFindsEveryModule() throws Exception {
        try (BusRig rig = BusRig.tcp(BusRig.FOUR_MODULES, BusRig.TIMING)) {
            rig.robot().echoRequests(true);
            ExplorationResult result = explorer(rig.bus()).explore("Echoed", new ExplorationListener() { });
            assertEquals(List.of(1, 2, 3, 4), result.modules().stream().map(FoundModule::address).toList(),
                    result.problems().toString());
            assertTrue(rig.bus().echoDetected());
            assertTrue(result.notes().stream().anyMatch(n -> n.contains("echoes every request")), result.notes()
                    .toString());
            MotorModuleProxy motor = new MotorModuleProxy(rig.bus(), 1, "Motor");
            motor.setMotor(1, 0.5); // a write: its reply equals the request, and still only the reply counts
            assertEquals(500, (short) rig.bus().readHoldingRegisters(1, 0, 1)[0]);
        }
    }

    @Test
    void aWriteFirstDoesNotFoolTheDetection() throws Exception {
        try (BusRig rig = BusRig.tcp(BusRig.FOUR_MODULES, BusRig.TIMING)) {
            rig.robot().echoRequests(true);
            MotorModuleProxy motor = new MotorModuleProxy(rig.bus(), 1, "Motor");
            motor.setMotor(1, 0.25);
            motor.setMotor(2, -0.25);
            assertEquals(List.of(250, -250), List.of((int) (short) rig.bus().readHoldingRegisters(1, 0, 2)[0],
                    (int) (short) rig.bus().readHoldingRegisters(1, 1, 1)[0]));
            assertTrue(rig.bus().echoDetected());
            assertFalse(new BumperModuleProxy(rig.bus(), 2, "Bumper").getSingleBumper(4));
        }
    }

    @Test
    void withCancellationOffTheEchoIsNamedWithTheFixAndTheScanStops() throws Exception {
        try (BusRig rig = BusRig.tcp(BusRig.FOUR_MODULES, BusRig.TIMING)) {
            rig.robot().echoRequests(true);
            rig.bus().echoCancellation(EchoCancellation.OFF);
            AdapterEchoException e = assertThrows(AdapterEchoException.class, () -> rig.bus().identify(2));
            assertTrue(e.getMessage().contains("the adapter echoes what it sends"), e.getMessage());
            assertTrue(e.getMessage().contains("--echo on"), e.getMessage());
            ExplorationResult result = explorer(rig.bus()).explore("Echoed", new ExplorationListener() { });
            assertEquals(1, result.problems().size(), "stopped at the first address: " + result.problems());
            assertTrue(result.notes().stream().anyMatch(n -> n.contains("echo cancellation is off")),
                    result.notes().toString());
        }
    }

    @Test
    void cancellationOnWithoutAnEchoingAdapterChangesNothing() throws Exception {
        try (BusRig rig = BusRig.tcp(BusRig.FOUR_MODULES, BusRig.TIMING)) {
            rig.bus().echoCancellation(EchoCancellation.ON);
            ExplorationResult result = explorer(rig.bus()).explore("Plain", new ExplorationListener() { });
            assertEquals(4, result.modules().size(), result.problems().toString());
            new MotorModuleProxy(rig.bus(), 1, "Motor").setMotor(1, 0.1);
            assertEquals(100, (short) rig.bus().readHoldingRegisters(1, 0, 1)[0]);
            assertFalse(rig.bus().echoDetected());
        }
    }
}
