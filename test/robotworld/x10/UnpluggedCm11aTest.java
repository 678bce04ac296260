package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import robotworld.bus.JSerialCommLink;
import robotworld.bus.SerialLink;
import robotworld.bus.SocatPty;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;

/**
 * A CM11A on a local serial device whose adapter is pulled out and plugged in again (a socat pty pair ended, then
 * made again under the same names, as a USB adapter's device path vanishes and comes back): commands fail while it
 * is out, with an {@link X10Exception}, and work again once it is back, with no restart of the program.
 */
@org.junit.jupiter.api.Timeout(120)
class UnpluggedCm11aTest {

    private static final X10Address A3 = X10Address.of('A', 3);
    private static final CM11aConfig CONFIG = Cm11aRig.fastConfig().withChecksumTimeout(Duration.ofSeconds(1))
            .withDeadInterfaceTimeout(Duration.ofSeconds(3));
    private static final Duration PATIENCE = Duration.ofSeconds(60);

    /** The interface's end of the pair, open. */
    private static SerialLink deviceEnd(SocatPty pty) throws java.io.IOException {
        SerialLink link = new JSerialCommLink(pty.b().toString(), X10Constants.CM11A_SERIAL);
        link.open();
        return link;
    }

    @Test
    void aSerialAdapterPulledOutAndPluggedInAgainIsUsedAgain() throws Exception {
        SocatPty pty = SocatPty.start();
        SimulatedCm11a sim = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance");
        sim.attach(deviceEnd(pty));
        try (CM11aController controller = CM11aController.open(pty.a().toString(), CONFIG)) {
            controller.on(A3);
            assertTrue(sim.appliance(A3).isOn());

            pty.unplug();
            assertFalse(Files.exists(pty.a()), "the device is gone");
            assertThrows(X10Exception.class, () -> controller.off(A3), "a command while the adapter is out");

            sim.close(); // the interface lost its side too; it comes back with the new device
            sim = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance");
            pty = SocatPty.startIn(pty.folder());
            sim.attach(deviceEnd(pty));
            // the new interface's appliance starts off: switching it on shows that the link works again
            long giveUp = System.nanoTime() + PATIENCE.toNanos();
            X10Exception last = null;
            while (!sim.appliance(A3).isOn() && System.nanoTime() < giveUp) {
                try {
                    controller.on(A3);
                } catch (X10Exception stillOut) {
                    last = stillOut;
                    Thread.sleep(100);
                }
            }
            assertTrue(sim.appliance(A3).isOn(), "the CM11A served again after it came back; last failure: " + last);
            controller.off(A3);
            assertFalse(sim.appliance(A3).isOn(), "and stays usable");
        } finally {
            sim.close();
            pty.close();
        }
    }
}
