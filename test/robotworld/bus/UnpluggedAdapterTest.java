package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;

/**
 * A robot bus on a local serial device whose adapter is pulled out and plugged in again (a socat pty pair ended,
 * then made again under the same names: the device path vanishes and comes back as a new terminal, as a USB
 * adapter's does): calls fail while it is out, with the bus's exception, and work again once it is back, with no
 * restart of the program.
 */
@org.junit.jupiter.api.Timeout(120)
class UnpluggedAdapterTest {

    @Test
    void aSerialAdapterPulledOutAndPluggedInAgainIsUsedAgain() throws Exception {
        SocatPty pty = SocatPty.start();
        SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.parse(BusRig.FOUR_MODULES, "test robot"));
        try {
            robot.serve(pty.a().toString());
            try (RS485Bus bus = new RS485Bus(pty.b().toString(), SerialSettings.eightNoneOne(115_200), BusRig.TIMING)) {
                BumperModuleProxy bumper = new BumperModuleProxy(bus, 2, "Bumper-Sensor");
                assertEquals(0, bumper.getAllBumper());

                pty.unplug();
                assertTrue(!Files.exists(pty.b()), "the device is gone");
                assertThrows(BusException.class, bumper::getAllBumper, "a call while the adapter is out");

                robot.close(); // the simulated modules lost their side too; they come back with the new device
                robot = SimulatedRobot.create(SimRobotConfigReader.parse(BusRig.FOUR_MODULES, "test robot"));
                pty = SocatPty.startIn(pty.folder());
                robot.serve(pty.a().toString());

                Integer answer = null;
                BusException last = null;
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
                while (answer == null && System.nanoTime() < deadline) {
                    try {
                        answer = bumper.getAllBumper();
                    } catch (BusException stillOut) {
                        last = stillOut;
                        Thread.sleep(100);
                    }
                }
                assertEquals(0, answer, "the bus answered again after the adapter came back; last failure: " + last);
                assertEquals(0, bumper.getAllBumper(), "and stays usable");
            }
        } finally {
            robot.close();
            pty.close();
        }
    }
}
