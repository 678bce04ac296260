package robotworld.sim.robot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The simulated modules' Modbus data models, driven through the server-side request handler. */
class SimModulesTest {

    private static final ModuleIdentity MOTOR = new ModuleIdentity("Vendor", "15B63A4", "1.0");

    private final World world = new World(2000, 1000, List.of(), new Pose(500, 500, 0), 100, 200, 200);
    private final SimMotorModule motor = new SimMotorModule(1, MOTOR, new ModuleFaults(1), 1000, 1, 2);
    private final SimServoModule servo = new SimServoModule(3, MOTOR, new ModuleFaults(1), 90);
    private final SimBumperModule bumper = new SimBumperModule(2, MOTOR, new ModuleFaults(1), world,
            Map.of(4, new SimBumperModule.Mount(0, 40)));
    private final SimIRDistanceModule ir = new SimIRDistanceModule(4, MOTOR, new ModuleFaults(1), world,
            Map.of(1, 0.0), 800);
    private final Simulation simulation = new Simulation(world, List.of(motor, servo, bumper, ir), 1);

    private static byte[] hex(String text) {
        return HexFormat.of().parseHex(text.replace(" ", ""));
    }

    private String ask(SimModule module, String request) {
        return HexFormat.ofDelimiter(" ").formatHex(simulation.respond(module, hex(request))).toUpperCase();
    }

    @Test
    void motorsRampTowardsTheSetSpeedAndDriveTheRobot() {
        assertEquals("06 00 00 01 F4", ask(motor, "06 00 00 01 F4"), "speed 500 per-mille accepted");
        assertEquals("06 00 01 01 F4", ask(motor, "06 00 01 01 F4"));
        assertEquals("02 01 03", ask(motor, "02 00 00 00 08"), "both ramping");
        simulation.step(0.25); // 1000 per-mille per second: 250 of 500
        assertEquals("02 01 03", ask(motor, "02 00 00 00 08"));
        simulation.step(0.5);
        assertEquals("02 01 00", ask(motor, "02 00 00 00 08"), "ramps done");
        assertTrue(world.pose().x() > 500);
        assertEquals("03 04 01 F4 01 F4", ask(motor, "03 00 00 00 02"));
    }

    /** Diagnostics 0x08, sub-function 0x0000 (return query data): every data word comes back, however many. */
    @Test
    void theEchoDiagnosticReturnsEveryDataWord() {
        assertEquals("08 00 00 A5 37", ask(motor, "08 00 00 A5 37"), "one word");
        assertEquals("08 00 00 12 34 AB CD 00 01", ask(motor, "08 00 00 12 34 AB CD 00 01"), "three words");
        assertEquals("08 00 00 00 01 00 02 00 03 00 04 00 05", ask(ir, "08 00 00 00 01 00 02 00 03 00 04 00 05"),
                "five words, another module type");
    }

    @Test
    void motorSpeedsOutsideTheRangeAreRefused() {
        assertEquals("86 03", ask(motor, "06 00 00 03 E9"), "1001 per-mille");
        assertEquals("06 00 00 FC 18", ask(motor, "06 00 00 FC 18"), "-1000 per-mille");
        assertEquals(-1000, motor.setSpeed(1));
        assertEquals("86 02", ask(motor, "06 00 08 00 00"), "no ninth motor");
    }

    @Test
    void servosTravelAtTheirSpeedAndReportMoving() {
        assertEquals("04 02 00 5A", ask(servo, "04 00 00 00 01"), "starts at 90");
        ask(servo, "06 00 00 00 B4");
        assertEquals("02 01 01", ask(servo, "02 00 00 00 01"));
        simulation.step(0.5);
        assertEquals(135, servo.angle(1), 1e-9);
        simulation.step(0.6);
        assertEquals("02 01 00", ask(servo, "02 00 00 00 01"));
        assertEquals("04 02 00 B4", ask(servo, "04 00 00 00 01"));
        assertEquals("86 03", ask(servo, "06 00 00 00 B5"), "181 degrees");
    }

    @Test
    void bumpersAndIrFollowTheWorld() {
        assertEquals("02 01 00", ask(bumper, "02 00 00 00 08"));
        assertEquals("04 02 03 20", ask(ir, "04 00 00 00 01"), "800: nothing within range");
        world.place(new Pose(1600, 500, 0));
        assertEquals("04 02 01 2C", ask(ir, "04 00 00 00 01"), "300 mm to the wall");
        assertEquals(Math.round(255.0 * 500 / 800), simulation.respond(ir, hex("04 00 07 00 01"))[3] & 0xFF);
        world.place(new Pose(1900, 500, 0));
        assertEquals("02 01 08", ask(bumper, "02 00 00 00 08"), "bumper 4 closed");
        assertEquals("04 02 00 00", ask(ir, "04 00 00 00 01"));
        assertEquals("04 02 00 FF", ask(ir, "04 00 07 00 01"), "raw reading at contact");
        assertEquals("04 02 03 20", ask(ir, "04 00 01 00 01"), "unmounted sensor 2 reads the range");
    }

    @Test
    void mandatoryCommandsAnswerAsTheSpecificationSays() {
        assertEquals("08 00 00 A5 02", ask(bumper, "08 00 00 A5 02"));
        assertEquals("08 00 00 00 01 00 02 00 03", ask(bumper, "08 00 00 00 01 00 02 00 03"), "any number of words");
        assertEquals("88 01", ask(bumper, "08 00 01 00 00"), "only Return Query Data");
        // report server ID: count, server id (= the address), run indicator last
        assertEquals("11 02 02 FF", ask(bumper, "11"));
        bumper.faults().stopped(true);
        assertArrayEquals(hex("11 02 02 00"), simulation.respond(bumper, hex("11")));
        String identification = ask(bumper, "2B 0E 01 00");
        assertEquals("2B 0E 01 01 00 00 03 00 06 56 65 6E 64 6F 72 01 07 31 35 42 36 33 41 34 02 03 31 2E 30",
                identification);
        assertEquals("2B 0E 04 01 00 00 01 01 07 31 35 42 36 33 41 34", ask(bumper, "2B 0E 04 01"),
                "one specific object");
        assertEquals("AB 02", ask(bumper, "2B 0E 04 07"), "no such object");
    }

    @Test
    void illegalRequestsGetTheRightExceptionCodes() {
        assertEquals("81 01", ask(bumper, "01 00 00 00 01"), "no coils");
        assertEquals("82 02", ask(bumper, "02 00 07 00 02"), "past the eighth input");
        assertEquals("82 03", ask(bumper, "02 00 00 00 00"), "count 0");
        assertEquals("84 02", ask(bumper, "04 00 00 00 01"), "no input registers");
        assertEquals("86 02", ask(bumper, "06 00 00 00 01"), "nothing to write");
        bumper.faults().refuseWith(4);
        assertEquals("82 04", ask(bumper, "02 00 00 00 08"), "fault injection");
    }

    @Test
    void writeMultipleRegistersWritesAndConfirms() {
        assertEquals("10 00 00 00 02", ask(servo, "10 00 00 00 02 04 00 0A 00 14"));
        assertEquals("03 04 00 0A 00 14", ask(servo, "03 00 00 00 02"));
        assertEquals("90 03", ask(servo, "10 00 00 00 02 03 00 0A 00"), "byte count does not match");
    }

    @Test
    void broadcastWritesReachEveryModuleWithoutAnswers() {
        simulation.broadcast(hex("06 00 02 00 0A"));
        assertEquals(10, motor.setSpeed(3));
        assertEquals("03 02 00 0A", ask(servo, "03 00 02 00 01"));
    }

    @Test
    void corruptionFaultsAreCountedDown() {
        ModuleFaults faults = new ModuleFaults(7).corruptNextReplies(2);
        assertTrue(faults.takeCorruption());
        assertTrue(faults.takeCorruption());
        assertFalse(faults.takeCorruption());
        faults.crcErrorRate(1);
        assertTrue(faults.takeCorruption());
    }
}
