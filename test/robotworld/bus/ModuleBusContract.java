package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.description.DescriptionLoader;
import robotworld.description.ModuleListType;
import robotworld.description.ModuleType;
import robotworld.description.RobotWorldAssembler;
import robotworld.sim.robot.Pose;
import robotworld.testsupport.ProjectFiles;

/**
 * The robot hardware acceptance, run once per link type: exploring the simulated four-module robot, driving it
 * into a wall, CRC retries, a silent module, and every proxy method.
 */
abstract class ModuleBusContract {

    /** Bumpers 4 and 6, the front ones. */
    private static final int FRONT_BUMPERS = 1 << 3 | 1 << 5;

    private BusRig rig;

    @TempDir
    Path folder;

    /** Sets up the simulated robot and a bus connected to it. */
    abstract BusRig connect(String configXml, BusTiming timing) throws Exception;

    @BeforeEach
    void start() throws Exception {
        rig = connect(BusRig.FOUR_MODULES, BusRig.TIMING);
    }

    @AfterEach
    void stop() throws Exception {
        if (rig != null) { // null when the set-up was skipped (no socat)
            rig.close();
        }
    }

    private RS485Bus bus() {
        return rig.bus();
    }

    @Test
    void exploringTheRobotWritesAValidDescriptionOfExactlyItsModules() throws Exception {
        RobotExplorer explorer = new RobotExplorer(bus(),
                new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions"))).host("robot-laptop");
        ExplorationResult result = explorer.explore("TestBot", new robotworld.bus.explore.ExplorationListener() { });
        assertEquals(List.of(), result.problems());
        Path file = folder.resolve("TestBot.xml");
        RobotWorldAssembler.write(result.description().orElseThrow(), file);

        ModuleListType robot = DescriptionLoader.loadRobot(file).getRobotDescription();
        assertEquals("TestBot", robot.getRobotName());
        assertEquals("robot-laptop", robot.getHost());
        assertEquals(bus().portName(), robot.getCOMPort());
        assertEquals("RS485Bus", robot.getTalkToBusClass());
        List<String> modules = new ArrayList<>();
        for (ModuleType module : robot.getModuleList()) {
            modules.add(module.getNodeNumber() + " " + module.getClass1() + " " + module.getNodeID() + " "
                    + module.getName() + " " + module.getVersion() + " " + module.getDocRef());
        }
        assertEquals(List.of(
                "1 MotorModule 15B63A4 Motor-Controller 1.0 docs/modules/motor.md",
                "2 BumperModule 15B63B2 Bumper-Sensor 1.0 docs/modules/bumper.md",
                "3 ServoModule 15B63A1 Servo-Controller 1.0 docs/modules/servo.md",
                "4 IRDistanceModule 15B63C7 IR-Distance-Sensor 1.0 docs/modules/ir-distance.md"), modules);
    }

    @Test
    void drivingIntoTheWallClosesTheFrontBumpersStopsTheRobotAndIrDistanceFalls() throws Exception {
        MotorModuleProxy motor = new MotorModuleProxy(bus(), 1, "Motor-Controller");
        BumperModuleProxy bumper = new BumperModuleProxy(bus(), 2, "Bumper-Sensor");
        IRDistanceModuleProxy ir = new IRDistanceModuleProxy(bus(), 4, "IR-Distance-Sensor");
        assertEquals(0, bumper.getAllBumper());
        assertEquals(800, ir.getSingleSensor(1), "the wall is 1350 mm away: beyond the range");

        // time goes by hand from here, 50 ms of simulated time per reading, so a busy machine reads as often
        rig.robot().simulation().close();
        motor.setMotor(1, 1.0);
        motor.setMotor(2, 1.0);
        List<Integer> front = new ArrayList<>();
        while ((bumper.getAllBumper() & FRONT_BUMPERS) != FRONT_BUMPERS) {
            front.add(ir.getSingleSensor(1));
            if (front.size() > 200) { // 10 simulated seconds: the 1350 mm take 4.5 s at full speed
                fail("the front bumpers did not close; robot at " + rig.robot().pose() + ", IR " + front);
            }
            rig.robot().simulation().step(0.05);
        }
        assertEquals(FRONT_BUMPERS, bumper.getAllBumper(), "only the front bumpers: " + bumper.getAllBumper());
        assertTrue(bumper.getSingleBumper(4) && bumper.getSingleBumper(6) && !bumper.getSingleBumper(1));
        front.add(ir.getSingleSensor(1));

        for (int i = 1; i < front.size(); i++) {
            assertTrue(front.get(i) <= front.get(i - 1), "IR distance never grows on the way: " + front);
        }
        assertTrue(front.stream().filter(d -> d < 800).distinct().count() >= 3, "several readings in range: " + front);
        assertTrue(front.get(front.size() - 1) <= 2, "touching: " + front);

        Pose touching = rig.robot().pose();
        assertEquals(1850, touching.x(), 1.0);
        rig.robot().simulation().step(1.0); // a simulated second, motors still at full speed
        assertEquals(touching.x(), rig.robot().pose().x(), 0.01, "the wall stops the robot");
        assertEquals(1.0, motor.getMotor(1));
        motor.setMotor(1, 0);
        motor.setMotor(2, 0);
    }

    @Test
    void corruptedRepliesAreRetried() {
        BumperModuleProxy bumper = new BumperModuleProxy(bus(), 2, "Bumper-Sensor");
        rig.robot().faults(2).corruptNextReplies(2);
        BusStatistics before = bus().statistics();
        assertEquals(0, bumper.getAllBumper());
        BusStatistics after = bus().statistics();
        assertEquals(2, after.crcErrors() - before.crcErrors());
        assertEquals(2, after.retries() - before.retries());

        rig.robot().faults(2).corruptNextReplies(3);
        BusCrcException e = assertThrows(BusCrcException.class, bumper::getAllBumper);
        assertTrue(e.getMessage().contains("BumperModule 'Bumper-Sensor' at address 2"), e.getMessage());
        assertEquals(0, bumper.getAllBumper(), "the module is fine again");
    }

    @Test
    void aSilentModuleTimesOutNamingModuleAndAddress() {
        IRDistanceModuleProxy ir = new IRDistanceModuleProxy(bus(), 4, "IR-Distance-Sensor");
        rig.robot().faults(4).silent(true);
        BusTimeoutException e = assertThrows(BusTimeoutException.class, () -> ir.getSingleSensor(1));
        assertEquals(4, e.address());
        assertTrue(e.getMessage().startsWith("IRDistanceModule 'IR-Distance-Sensor' at address 4 on "
                + bus().portName() + ": no reply"), e.getMessage());
        rig.robot().faults(4).silent(false);
        assertEquals(800, ir.getSingleSensor(1), "calls work again once it answers");
    }

    @Test
    void setServoWaitsForTheTargetAndSetServoQuietDoesNot() throws Exception {
        // a servo ten times slower than the rig's: a 90 degree trip takes 1 s, so it cannot be over before the next
        // call however busy the machine is
        rig.close();
        rig = connect(BusRig.FOUR_MODULES.replace("speed=\"90\"", "speed=\"9\""), BusRig.TIMING);
        ServoModuleProxy servo = new ServoModuleProxy(bus(), 3, "Servo-Controller");
        assertEquals(90, servo.getServo(1));
        servo.setServo(1, 180);
        assertFalse(servo.isMoving(1));
        assertEquals(180, servo.getServo(1));

        servo.setServoQuiet(2, 0);
        assertTrue(servo.isMoving(2), "a 1 s trip has only begun");
        waitUntil(() -> !servo.isMoving(2));
        assertEquals(0, servo.getServo(2));
    }

    @Test
    void aServoThatCannotGetThereInTimeFails() throws Exception {
        rig.close();
        rig = connect(BusRig.FOUR_MODULES.replace("speed=\"90\"", "speed=\"1\""),
                BusRig.TIMING.withServoMoveTimeout(Duration.ofMillis(200)));
        BusTimeoutException e = assertThrows(BusTimeoutException.class,
                () -> new ServoModuleProxy(bus(), 3, "Arm").setServo(1, 180));
        assertTrue(e.getMessage().startsWith("ServoModule 'Arm' at address 3"), e.getMessage());
        assertTrue(e.getMessage().contains("servo 1 did not reach 180 degrees within 200 ms"), e.getMessage());
    }

    @Test
    void motorSpeedsGoOutQuietlyAndReadBack() {
        MotorModuleProxy motor = new MotorModuleProxy(bus(), 1);
        motor.setMotorQuiet(3, -0.25);
        motor.setMotorQuiet(4, 0.5);
        assertEquals(-0.25, motor.getMotor(3));
        assertEquals(0.5, motor.getMotor(4));
        assertTrue(motor.isRamping(4) || motor.getMotor(4) == 0.5);
    }

    @Test
    void irReadsAllSensorsAsTextRawBytesAndCache() {
        IRDistanceModuleProxy ir = new IRDistanceModuleProxy(bus(), 4);
        // sensor 1 faces the far wall (beyond range); 2 and 3 see the side walls 350 mm away
        assertEquals("800 350 350 800 800 800 800", ir.getAllSensors());
        int[] raw = ir.getAllSensors_ByteRep();
        assertArrayEquals(new int[] {0, 143, 143, 0, 0, 0, 0}, raw);
        long before = bus().statistics().transactions();
        assertEquals(350, ir.getSingleSensor_Cached(2));
        assertEquals(before, bus().statistics().transactions(), "cached reads stay off the bus");
        assertEquals(800, ir.getSingleSensor(1));
    }

    @Test
    void badArgumentsAreRefusedBeforeAnythingGoesOnTheBus() {
        long before = bus().statistics().transactions();
        MotorModuleProxy motor = new MotorModuleProxy(bus(), 1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> motor.setMotor(9, 0));
        assertEquals("motor number 9 is outside 1..8", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> motor.setMotor(1, 1.01));
        assertThrows(IllegalArgumentException.class, () -> motor.setMotorQuiet(1, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new ServoModuleProxy(bus(), 3).setServo(1, 181));
        assertThrows(IllegalArgumentException.class, () -> new ServoModuleProxy(bus(), 3).setServoQuiet(0, 90));
        assertThrows(IllegalArgumentException.class, () -> new BumperModuleProxy(bus(), 2).getSingleBumper(9));
        assertThrows(IllegalArgumentException.class, () -> new IRDistanceModuleProxy(bus(), 4).getSingleSensor(8));
        assertThrows(IllegalArgumentException.class, () -> new BumperModuleProxy(bus(), 248));
        assertEquals(before, bus().statistics().transactions());
    }

    @Test
    void proxiesAreFoundByTheNamingConvention() {
        assertTrue(ModuleProxies.create("BumperModule", bus(), 2, "Front") instanceof BumperModuleProxy);
        assertTrue(ModuleProxies.create("IRDistanceModule", bus(), 4, null) instanceof IRDistanceModuleProxy);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ModuleProxies.create("LaserModule", bus(), 5, null));
        assertTrue(e.getMessage().contains("robotworld.bus.LaserModuleProxy"), e.getMessage());
    }

    private static void waitUntil(BooleanSupplier condition) {
        long deadline = System.nanoTime() + 5_000_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                fail("condition not reached in 5 s");
            }
        }
    }
}
