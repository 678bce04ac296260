package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import robotworld.bus.explore.AddressProblem;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.testsupport.ProjectFiles;

/**
 * Exploration at byte level: an address whose exchanges are disturbed is never counted as empty on a silence that
 * followed a disturbance in the same exchange; when it cannot be asked undisturbed, it is reported.
 */
class ExplorationDisturbanceTest {

    @Test
    void anAddressCutShortThenSilentOnEveryAskIsReportedNotTakenForEmpty() throws Exception {
        // what a 9600-baud module explored at 115200 on a busy machine does: its reply is cut by a stall after the
        // first byte (a CRC error for that attempt), and the retry's reply starts later than the timeout
        AtomicInteger toTwo = new AtomicInteger();
        ScriptedBusLink link = new ScriptedBusLink(request -> {
            if (request[0] != 2) {
                return List.of();
            }
            return toTwo.getAndIncrement() % 2 == 0 ? List.of(new byte[] {2}) : List.of();
        });
        BusTiming timing = BusTiming.defaults().withFrameGap(Duration.ZERO).withResponseTimeout(Duration.ofMillis(50));
        try (RS485Bus bus = new RS485Bus(link, SerialSettings.eightNoneOne(115_200), timing)) {
            ExplorationResult result = new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve(
                    "ModuleDescriptions"))).addresses(1, 3).explore("Disturbed", new ExplorationListener() { });
            assertEquals(List.of(2), result.problems().stream().map(AddressProblem::address).toList(),
                    result.problems().toString());
            AddressProblem problem = result.problems().get(0);
            assertEquals(AddressProblem.Kind.DISTURBED, problem.kind());
            assertTrue(problem.message().contains("could not be asked again undisturbed"), problem.message());
            assertTrue(toTwo.get() > 2, "asked again after the scan, " + toTwo.get() + " requests to address 2");
        }
    }

    @Test
    void anAddressDisturbedOnceAndQuietWhenAskedAgainIsEmpty() throws Exception {
        // noise while probing 2, then an undisturbed silence: nobody there, and nothing to report
        AtomicInteger toTwo = new AtomicInteger();
        ScriptedBusLink link = new ScriptedBusLink(request -> request[0] == 2 && toTwo.getAndIncrement() == 0
                ? List.of(new byte[] {2, 0x55, (byte) 0xAA, 0x13}) : List.of());
        BusTiming timing = BusTiming.defaults().withFrameGap(Duration.ZERO).withResponseTimeout(Duration.ofMillis(50));
        try (RS485Bus bus = new RS485Bus(link, SerialSettings.eightNoneOne(115_200), timing)) {
            ExplorationResult result = new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve(
                    "ModuleDescriptions"))).addresses(1, 3).explore("Quiet", new ExplorationListener() { });
            assertEquals(List.of(), result.problems());
            assertEquals(List.of(), result.modules());
            assertTrue(toTwo.get() >= 2, "address 2 was asked again");
        }
    }
}
