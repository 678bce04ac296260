package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.Conditions.eventually;
import static robotworld.xvsm.XVSMWorld.BUMPER;
import static robotworld.xvsm.XVSMWorld.ENVIRONMENT;
import static robotworld.xvsm.XVSMWorld.FAN;
import static robotworld.xvsm.XVSMWorld.IR;
import static robotworld.xvsm.XVSMWorld.LAMP;
import static robotworld.xvsm.XVSMWorld.MOTOR;
import static robotworld.xvsm.XVSMWorld.ROBOT;
import static robotworld.xvsm.XVSMWorld.SERVO;

import java.util.function.Consumer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.core.BumperModule;
import robotworld.core.IRDistanceModule;
import robotworld.core.MotorModule;
import robotworld.core.ServoModule;
import robotworld.core.X10ApplianceModule;
import robotworld.core.X10LampModule;
import robotworld.sim.SimulatedLampModule;

/**
 * Every method of every module interface, called through a Remote proxy on another computer (its own connection
 * and host name), gives what the same call gives on the Local proxy and does the same to the simulated hardware.
 */
class RemoteMatchesLocalTest {

    private XVSMWorld world;
    private XVSMRuntime laptop;

    @BeforeEach
    void start() throws Exception {
        world = XVSMWorld.start();
        laptop = world.host("laptop");
    }

    @AfterEach
    void stop() throws Exception {
        world.close();
    }

    @Test
    void bumperReadsMatch() {
        BumperModule remote = new XVSMBumperModuleRemote(laptop, ROBOT, BUMPER);
        assertEquals(XVSMWorld.CONTACT_MASK, world.bumper.getAllBumper());
        assertEquals(world.bumper.getAllBumper(), remote.getAllBumper());
        for (int bumper = 1; bumper <= BumperModule.BUMPERS; bumper++) {
            assertEquals(world.bumper.getSingleBumper(bumper), remote.getSingleBumper(bumper), "bumper " + bumper);
        }
        assertTrue(remote.getSingleBumper(4));
        assertFalse(remote.getSingleBumper(1));
    }

    @Test
    void irReadsMatch() {
        IRDistanceModule remote = new XVSMIRDistanceModuleRemote(laptop, ROBOT, IR);
        assertEquals(world.ir.getAllSensors(), remote.getAllSensors());
        assertArrayEquals(world.ir.getAllSensors_ByteRep(), remote.getAllSensors_ByteRep());
        for (int sensor = 1; sensor <= IRDistanceModule.SENSORS; sensor++) {
            assertEquals(world.ir.getSingleSensor(sensor), remote.getSingleSensor(sensor), "sensor " + sensor);
            assertEquals(world.ir.getSingleSensor_Cached(sensor), remote.getSingleSensor_Cached(sensor),
                    "cached sensor " + sensor);
        }
        // front: touching the wall; sides: 350 mm to the walls at y = 0 and 1000; 4..7 unmounted: the range
        assertEquals("0 350 350 800 800 800 800", remote.getAllSensors());
    }

    @Test
    void motorSpeedsArriveAsOnTheLocalSide() {
        MotorModule remote = new XVSMMotorModuleRemote(laptop, ROBOT, MOTOR);
        remote.setMotor(1, -0.25);
        assertEquals(-0.25, world.motorHardware.getMotor(1));
        remote.setMotorQuiet(2, -0.5);
        eventually("the quiet speed is set", () -> world.motorHardware.getMotor(2) == -0.5);
        remote.setMotor(3, 0.3334); // per-mille on the way, as on the bus
        assertEquals(0.333, world.motorHardware.getMotor(3));

        world.motor.setMotor(3, 0.3334);
        assertEquals(0.333, world.motorHardware.getMotor(3));
        world.motor.setMotorQuiet(1, 0.0);
        eventually("the local quiet speed is set", () -> world.motorHardware.getMotor(1) == 0.0);
    }

    @Test
    void servoPositionsArriveAsOnTheLocalSide() {
        ServoModule remote = new XVSMServoModuleRemote(laptop, ROBOT, SERVO);
        remote.setServo(1, 120);
        assertEquals(120, world.servoHardware.getServo(1), "setServo returns once the servo is there");
        remote.setServoQuiet(2, 45);
        eventually("the quiet servo gets there", () -> world.servoHardware.getServo(2) == 45);

        world.servo.setServo(1, 30);
        assertEquals(30, world.servoHardware.getServo(1));
        world.servo.setServoQuiet(2, 90);
        eventually("the local quiet servo gets there", () -> world.servoHardware.getServo(2) == 90);
    }

    @Test
    void lampDoesTheSameRemotelyAndLocally() {
        X10LampModule remote = new XVSMX10LampModuleRemote(laptop, ENVIRONMENT, LAMP);
        SimulatedLampModule lamp = world.cm11a.lamp(XVSMWorld.LAMP_ADDRESS);
        runLampSequence(remote, lamp);
        runLampSequence(world.lamp, lamp);
    }

    private static void runLampSequence(X10LampModule module, SimulatedLampModule lamp) {
        module.on();
        assertEquals(100, lamp.brightnessPercent());
        module.dim(50);
        assertEquals(50, lamp.brightnessPercent());
        module.brighten(25);
        assertEquals(17, lamp.level());
        module.off();
        assertEquals(0, lamp.brightnessPercent());
    }

    @Test
    void applianceDoesTheSameRemotelyAndLocally() {
        X10ApplianceModule remote = new XVSMX10ApplianceModuleRemote(laptop, ENVIRONMENT, FAN);
        Consumer<X10ApplianceModule> onOff = module -> {
            module.on();
            assertTrue(world.cm11a.appliance(XVSMWorld.FAN_ADDRESS).isOn());
            module.off();
            assertFalse(world.cm11a.appliance(XVSMWorld.FAN_ADDRESS).isOn());
        };
        onOff.accept(remote);
        onOff.accept(world.fan);
    }

    @Test
    void argumentsAreRefusedRemotelyAsLocallyWithoutSendingAnything() {
        MotorModule remoteMotor = new XVSMMotorModuleRemote(laptop, ROBOT, MOTOR);
        assertSameRefusal(() -> world.motor.setMotor(9, 0), () -> remoteMotor.setMotor(9, 0));
        assertSameRefusal(() -> world.motor.setMotorQuiet(1, 1.5), () -> remoteMotor.setMotorQuiet(1, 1.5));
        ServoModule remoteServo = new XVSMServoModuleRemote(laptop, ROBOT, SERVO);
        assertSameRefusal(() -> world.servo.setServo(1, 181), () -> remoteServo.setServo(1, 181));
        BumperModule remoteBumper = new XVSMBumperModuleRemote(laptop, ROBOT, BUMPER);
        assertSameRefusal(() -> world.bumper.getSingleBumper(0), () -> remoteBumper.getSingleBumper(0));
        IRDistanceModule remoteIr = new XVSMIRDistanceModuleRemote(laptop, ROBOT, IR);
        assertSameRefusal(() -> world.ir.getSingleSensor(8), () -> remoteIr.getSingleSensor(8));
        X10LampModule remoteLamp = new XVSMX10LampModuleRemote(laptop, ENVIRONMENT, LAMP);
        assertSameRefusal(() -> world.lamp.dim(101), () -> remoteLamp.dim(101));
        assertEquals(0, laptop.space().describeContainer(world.motor.requestContainer()).size());
    }

    private static void assertSameRefusal(Runnable local, Runnable remote) {
        IllegalArgumentException expected = assertThrows(IllegalArgumentException.class, local::run);
        IllegalArgumentException actual = assertThrows(IllegalArgumentException.class, remote::run);
        assertEquals(expected.getMessage(), actual.getMessage());
    }
}
