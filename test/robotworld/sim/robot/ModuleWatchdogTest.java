package robotworld.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HexFormat;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The communication watchdog of the simulated modules: holding register 0x0100 (timeout ms, 0 = off), discrete
 * input 0x0100 (tripped), motors to 0 when no frame addressed to the module came for the timeout. Time is given
 * by hand, so nothing here depends on the machine's speed.
 */
class ModuleWatchdogTest {

    private static final ModuleIdentity IDENTITY = new ModuleIdentity("Vendor", "15B63A4", "1.0");
    private static final long MS = 1_000_000L;

    private final World world = new World(2000, 1000, List.of(), new Pose(500, 500, 0), 100, 200, 200);
    private final SimMotorModule motor = new SimMotorModule(1, IDENTITY, new ModuleFaults(1), 0, 1, 2);
    private final SimServoModule servo = new SimServoModule(3, IDENTITY, new ModuleFaults(1), 0);
    private final Simulation simulation = new Simulation(world, List.of(motor, servo), 1);

    private String ask(SimModule module, String request) {
        byte[] pdu = HexFormat.of().parseHex(request.replace(" ", ""));
        return HexFormat.ofDelimiter(" ").formatHex(simulation.respond(module, pdu)).toUpperCase();
    }

    @Test
    void offAtPowerUpSoAMotorNeverStopsByItself() {
        assertEquals("03 02 00 00", ask(motor, "03 01 00 00 01"), "timeout register reads 0");
        ask(motor, "06 00 00 01 F4");
        simulation.checkWatchdogs(System.nanoTime() + 60_000 * MS);
        assertEquals(500, motor.setSpeed(1));
        assertEquals("02 01 00", ask(motor, "02 01 00 00 01"), "not tripped");
    }

    @Test
    void aSilentMasterStopsTheMotorsAfterTheTimeoutAndTheStatusBitSaysSo() {
        assertEquals("06 01 00 01 F4", ask(motor, "06 01 00 01 F4"), "armed with 500 ms");
        assertEquals("03 02 01 F4", ask(motor, "03 01 00 00 01"));
        ask(motor, "06 00 00 01 F4");
        ask(motor, "06 00 01 FE 0C");
        long lastFrame = System.nanoTime();
        simulation.checkWatchdogs(lastFrame + 450 * MS);
        assertEquals(500, motor.setSpeed(1), "still within the timeout");
        simulation.checkWatchdogs(lastFrame + 510 * MS);
        assertEquals(0, motor.setSpeed(1));
        assertEquals(0, motor.setSpeed(2));
        assertTrue(motor.watchdogTripped());
        assertEquals(1, motor.watchdogTrips());
        assertEquals("02 01 01", ask(motor, "02 01 00 00 01"), "the master reads the tripped bit");
        assertEquals("02 01 01", ask(motor, "02 01 00 00 01"), "latched until the timeout is written again");
        ask(motor, "10 01 00 00 01 02 01 F4");
        assertEquals("02 01 00", ask(motor, "02 01 00 00 01"), "writing the timeout clears it");
        assertFalse(motor.watchdogTripped());
    }

    @Test
    void everyFrameToTheModuleFeedsItButBroadcastsDoNot() {
        ask(motor, "06 01 00 00 64"); // 100 ms
        ask(motor, "06 00 00 01 F4");
        long start = System.nanoTime();
        for (int i = 1; i <= 10; i++) {
            ask(motor, "02 00 00 00 08"); // any read feeds it
            simulation.checkWatchdogs(System.nanoTime() + 90 * MS);
        }
        assertEquals(500, motor.setSpeed(1), "fed all along");
        simulation.broadcast(HexFormat.of().parseHex("0600020064"));
        simulation.checkWatchdogs(System.nanoTime() + 110 * MS);
        assertEquals(0, motor.setSpeed(1), "a broadcast is no sign of a master talking to this module");
        assertTrue(System.nanoTime() - start >= 0);
    }

    @Test
    void theTrippedBitIsSetOnlyOnceTheModuleIsInItsSafeState() {
        // a reader of the bit (the master, a monitor) must never find it set while the module still runs
        List<Boolean> trippedWhileStopping = new java.util.ArrayList<>();
        SimModule module = new SimModule(5, IDENTITY, new ModuleFaults(5)) {
            @Override
            void enterSafeState() {
                trippedWhileStopping.add(watchdogTripped());
            }

            @Override
            public String moduleClass() {
                return "TestModule";
            }
        };
        Simulation own = new Simulation(world, List.of(module), 1);
        own.respond(module, HexFormat.of().parseHex("0601000064")); // 100 ms
        own.checkWatchdogs(System.nanoTime() + 200 * MS);
        assertEquals(List.of(false), trippedWhileStopping, "stopped first, then the bit set");
        assertTrue(module.watchdogTripped());
        own.checkWatchdogs(System.nanoTime() + 400 * MS);
        assertEquals(1, module.watchdogTrips(), "once per silence");
    }

    @Test
    void aServoHoldsWhenItsWatchdogTrips() {
        ask(servo, "06 01 00 00 64");
        ask(servo, "06 00 00 00 2D"); // 45 degrees
        simulation.checkWatchdogs(System.nanoTime() + 200 * MS);
        assertTrue(servo.watchdogTripped());
        assertEquals("04 02 00 2D", ask(servo, "04 00 00 00 01"), "holds its position");
        assertEquals("03 02 00 2D", ask(servo, "03 00 00 00 01"), "and its target");
    }

    @Test
    void otherAccessesToTheWatchdogAddressesAreRefusedAsBefore() {
        assertEquals("83 02", ask(motor, "03 00 07 00 0A"), "a range across the watchdog register");
        assertEquals("84 02", ask(motor, "04 01 00 00 01"), "no input register there");
    }
}
