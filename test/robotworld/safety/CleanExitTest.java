package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.safety.SafetyRig.eventually;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.ServoModuleProxy;
import robotworld.core.ServoModule;
import robotworld.sim.robot.SimServoModule;
import robotworld.space.Capi;
import robotworld.space.Entry;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;
import robotworld.xvsm.ActuatorStoppedException;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMServoModuleLocal;

/**
 * Rule 1: however a program that serves actuators ends (normal return, uncaught exception, SIGTERM,
 * {@code System.exit}), its motors are at 0 afterwards, its servos hold (no new target is sent), and the stop is
 * logged and published.
 */
class CleanExitTest {

    private static final Duration START = Duration.ofSeconds(60);

    @TempDir
    Path temp;

    private SafetyRig rig;

    @BeforeEach
    void startRig() throws Exception {
        rig = SafetyRig.start();
    }

    @AfterEach
    void stopRig() {
        rig.close();
    }

    @Test
    void closingTheRuntimeStopsTheMotorsAndRecordsWhy() throws Exception {
        try (Capi observer = RemoteSpace.open(rig.space.uri())) {
            XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
            XVSMMotorModuleLocal motor = serveMotor(runtime);
            motor.setMotor(1, 0.45);
            motor.setMotor(2, -0.45);
            assertEquals(450, rig.motorSpeed(1));
            assertEquals(-450, rig.motorSpeed(2));

            runtime.close();

            assertTrue(rig.motorsStopped(), "the close returns after the motors are at 0");
            List<StopRecord> stops = stopRecords(observer, 1);
            StopRecord stop = stops.get(0);
            assertEquals(SafetyRig.ROBOT, stop.participant());
            assertEquals(SafetyRig.MOTOR, stop.module());
            assertEquals(StopCause.PROGRAM_ENDED, stop.cause());
            assertEquals("motors 1-8 set to 0", stop.action());
            assertEquals(runtime.programId(), stop.stoppedBy());
        }
    }

    @Test
    void aFailedProgramStopsItsMotorsAndRefusesLaterCommands() throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            XVSMMotorModuleLocal motor = serveMotor(runtime);
            motor.setMotor(1, 0.45);
            runtime.failed(new IllegalStateException("boom"));
            assertTrue(rig.motorsStopped());
            // a thread of the failed program that goes on commanding cannot start the motor again
            ActuatorStoppedException refused = assertThrows(ActuatorStoppedException.class,
                    () -> motor.setMotor(1, 0.3));
            assertTrue(refused.getMessage().contains("program-failed"), refused.getMessage());
            assertTrue(refused.getMessage().contains("boom"), refused.getMessage());
            assertEquals(0, rig.motorSpeed(1), "the refused command was not carried out");
        }
    }

    @Test
    void closingAMotorProxyStopsItsMotors() throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            XVSMMotorModuleLocal motor = serveMotor(runtime);
            motor.setMotor(2, 0.2);
            motor.close();
            assertTrue(rig.motorsStopped());
        }
    }

    @Test
    void aProgramThatEndsLeavesItsServoHoldingItsTargetAndSendsItNothing() throws Exception {
        List<String> sent = new java.util.concurrent.CopyOnWriteArrayList<>();
        try (Capi observer = RemoteSpace.open(rig.space.uri());
             RS485Bus reader = bus()) {
            XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
            RS485Bus bus = runtime.own(bus());
            ServoModuleProxy hardware = new ServoModuleProxy(bus, 3, SafetyRig.SERVO);
            // what reaches the module's hardware proxy, i.e. the bus
            ServoModule recording = new ServoModule() {
                @Override
                public void setServo(int servoNr, int position) {
                    sent.add("setServo " + servoNr + " " + position);
                    hardware.setServo(servoNr, position);
                }

                @Override
                public void setServoQuiet(int servoNr, int position) {
                    sent.add("setServoQuiet " + servoNr + " " + position);
                    hardware.setServoQuiet(servoNr, position);
                }
            };
            XVSMServoModuleLocal servo = runtime.own(new XVSMServoModuleLocal(runtime, SafetyRig.ROBOT,
                    SafetyRig.SERVO, recording));
            servo.setServoQuiet(1, 0); // from 90 degrees at 90 degrees/s: under way for a second

            runtime.close();

            assertEquals(List.of("setServoQuiet 1 0"), sent, "ending sent the servo no new target");
            StopRecord stop = stopRecords(observer, 1).get(0);
            assertEquals(SafetyRig.SERVO, stop.module());
            assertEquals(StopCause.PROGRAM_ENDED, stop.cause());
            assertEquals(SafeStates.SERVOS_HOLD, stop.action());
            assertEquals(0, reader.readHoldingRegisters(3, 0, 1)[0], "its target is still the one it was given");
            eventually("the servo completes its move and holds there",
                    () -> ((SimServoModule) rig.robot.module(3)).angle(1) == 0);
        }
    }

    @Test
    void aProgramThatReturnsStopsItsMotors() throws Exception {
        childEndsAndMotorsAreStopped("return", 0);
    }

    @Test
    void aProgramThatThrowsStopsItsMotors() throws Exception {
        String output = childEndsAndMotorsAreStopped("throw", 1);
        assertTrue(output.contains("program-failed"), output);
    }

    @Test
    void aProgramThatCallsSystemExitStopsItsMotors() throws Exception {
        String output = childEndsAndMotorsAreStopped("exit", 3);
        assertTrue(output.contains("shutdown"), output);
    }

    @Test
    void aProgramStoppedWithSigtermStopsItsMotors() throws Exception {
        try (ChildProgram child = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "serve", "wait",
                rig.spaceUrl, rig.busPort)) {
            child.awaitLine("READY", START);
            assertEquals(450, rig.motorSpeed(1));
            child.terminate();
            int exit = child.awaitExit(START);
            assertNotEquals(0, exit, "SIGTERM ends the JVM with 143");
            assertTrue(rig.motorsStopped(), "motors at 0 once the program has ended; its output:\n" + child.output());
            assertTrue(child.output().contains("(shutdown: the JVM is shutting down"), child.output());
        }
    }

    /** Runs the child in {@code mode}; checks its exit code and that the motors are at 0 when it has ended. */
    private String childEndsAndMotorsAreStopped(String mode, int exitCode) throws Exception {
        try (ChildProgram child = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "serve", mode,
                rig.spaceUrl, rig.busPort)) {
            int exit = child.awaitExit(START);
            String output = child.output();
            assertTrue(output.contains("READY"), output);
            assertEquals(exitCode, exit, output);
            assertTrue(rig.motorsStopped(), "motors at 0 once the program has ended; its output:\n" + output);
            assertTrue(output.contains("SafetyBot/Motor stopped at"), output);
            return output;
        }
    }

    private RS485Bus bus() throws Exception {
        return new RS485Bus(rig.busPort, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO));
    }

    private XVSMMotorModuleLocal serveMotor(XVSMRuntime runtime) throws Exception {
        SafetyRig.relax(runtime);
        RS485Bus bus = runtime.own(bus());
        return runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT, SafetyRig.MOTOR,
                new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
    }

    /** Waits until the space holds at least {@code count} stop records; returns them, oldest first. */
    static List<StopRecord> stopRecords(Capi space, int count) {
        List<Entry> entries = space.read(SafetyContainers.stops(space), Timeout.ofMillis(30_000),
                Selector.fifo(count));
        assertFalse(entries.isEmpty());
        return entries.stream().map(StopRecord::parse).toList();
    }
}
