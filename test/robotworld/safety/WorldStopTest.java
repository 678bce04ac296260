package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.safety.SafetyRig.eventually;

import java.io.PrintWriter;
import java.io.StringWriter;
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
import robotworld.explorer.cli.Rwe;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.xvsm.ActuatorStoppedException;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * Rule 5: {@code rwe stop WORLD}, from a computer that neither serves nor commands anything, stops every actuator of
 * the world through the space; every program answers for its modules; unreachable actuators make it fail.
 */
class WorldStopTest {

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
    void rweStopFromAThirdProgramStopsEveryActuatorAndReportsEachModule() throws Exception {
        Path world = rig.writeWorld(temp.resolve("safety-world.xml"));
        try (ChildProgram robot = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "serve", "wait",
                rig.spaceUrl, rig.busPort);
             ChildProgram room = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "room", rig.spaceUrl,
                     rig.x10Port)) {
            robot.awaitLine("READY", START);
            room.awaitLine("READY", START);
            assertEquals(450, rig.motorSpeed(1));
            try (ChildProgram stop = ChildProgram.start(temp, List.of(), Rwe.class, "stop", world.toString(),
                    "--reason", "end of the lab session")) {
                int exit = stop.awaitExit(START);
                String output = stop.output();
                assertEquals(0, exit, output);
                assertTrue(rig.motorsStopped(), output);
                assertTrue(output.contains("SafetyBot/Motor   stopped by robot-pc#"), output);
                assertTrue(output.contains(": motors 1-8 set to 0"), output);
                assertTrue(output.contains("SafetyBot/Bumper  no actuator (robot-pc#"), output);
                assertTrue(output.contains("SafetyRoom/Lamp   stopped by room-pc#"), output);
                assertTrue(output.contains("left as it is (X10 safe state: unchanged)"), output);
                assertTrue(output.contains("3 of 3 modules answered"), output);
                assertTrue(output.contains("every actuator is in its safe state"), output);
            }
            assertTrue(rig.cm11a.lamp(robotworld.x10.X10Address.of('A', 1)).isOn(), "X10 left as it is");
            assertTrue(robot.output().contains("(stop-request: asked by "), robot.output());
            assertTrue(robot.output().contains("(rwe stop): end of the lab session)"), robot.output());
        }
    }

    @Test
    void rweStopSaysWhichActuatorsItCouldNotReachAndFails() throws Exception {
        Path world = rig.writeWorld(temp.resolve("safety-world.xml"));
        try (ChildProgram robot = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "serve", "wait",
                rig.spaceUrl, rig.busPort)) {
            robot.awaitLine("READY", START);
            StringWriter out = new StringWriter();
            StringWriter err = new StringWriter();
            int exit = Rwe.run(new PrintWriter(out), new PrintWriter(err), "stop", world.toString(), "--wait", "1");
            assertEquals(1, exit, out + "\n" + err);
            assertTrue(rig.motorsStopped());
            String report = out.toString();
            assertTrue(report.contains("SafetyRoom/Lamp   unreachable: no program serving it answered"), report);
            assertTrue(report.contains("2 of 3 modules answered"), report);
            assertTrue(report.contains("1 actuator(s) NOT confirmed stopped: SafetyRoom/Lamp"), report);
        }
    }

    @Test
    void aStoppedCommanderIsToldOnItsNextCallAndMayCommandAgain() throws Exception {
        try (ChildProgram robot = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "serve", "wait",
                rig.spaceUrl, rig.busPort);
             XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop");
             Capi ops = RemoteSpace.open(rig.space.uri())) {
            robot.awaitLine("READY", START);
            XVSMMotorModuleRemote motor = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT,
                    SafetyRig.MOTOR));
            motor.setMotor(1, 0.7);
            WorldStop.Result result = WorldStop.stop(ops, "ops", "test", List.of(
                    new WorldStop.Target(SafetyRig.ROBOT, SafetyRig.MOTOR, true)), Duration.ofSeconds(30));
            assertTrue(result.complete(), result.toString());
            assertTrue(rig.motorsStopped());
            ActuatorStoppedException told = assertThrows(ActuatorStoppedException.class, () -> motor.setMotor(1, 0.7));
            assertTrue(told.getMessage().contains("stop-request"), told.getMessage());
            assertEquals(0, rig.motorSpeed(1));
            motor.setMotor(1, 0.7);
            assertEquals(700, rig.motorSpeed(1));
        }
    }

    @Test
    void aStopOfOneWorldLeavesTheActuatorsOfOthersAlone() throws Exception {
        try (ChildProgram robot = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "serve", "wait",
                rig.spaceUrl, rig.busPort);
             Capi ops = RemoteSpace.open(rig.space.uri())) {
            robot.awaitLine("READY", START);
            WorldStop.Result result = WorldStop.stop(ops, "ops", "another world", List.of(
                    new WorldStop.Target("OtherBot", "Motor", true)), Duration.ofMillis(500));
            assertFalse(result.complete());
            assertEquals(1, result.outcomes().size(), result.toString());
            assertEquals(450, rig.motorSpeed(1), "not a participant of the stopped world");
        }
    }

    @Test
    void theStopRecordsSayWhoStoppedWhatAndWhy() throws Exception {
        try (ChildProgram robot = ChildProgram.start(temp, SafetyRig.RELAXED, SafetyChild.class, "serve", "wait",
                rig.spaceUrl, rig.busPort);
             Capi ops = RemoteSpace.open(rig.space.uri())) {
            robot.awaitLine("READY", START);
            WorldStop.Result result = WorldStop.stop(ops, "ops-laptop (test)", "why not", List.of(
                    new WorldStop.Target(SafetyRig.ROBOT, SafetyRig.MOTOR, true)), Duration.ofSeconds(30));
            StopRecord record = CleanExitTest.stopRecords(ops, 1).get(0); // waits for it
            assertEquals(StopCause.STOP_REQUEST, record.cause());
            assertEquals(result.request().id(), record.request());
            assertEquals("asked by ops-laptop (test): why not", record.reason());
            assertTrue(record.stoppedBy().startsWith("robot-pc#"), record.toString());
        }
    }

    @Test
    void aProgramHearsAStopIssuedTheMomentItServesItsFirstActuator() throws Exception {
        for (int round = 0; round < 5; round++) {
            try (XVSMRuntime robot = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
                 Capi ops = RemoteSpace.open(rig.space.uri())) {
                SafetyRig.relax(robot);
                RS485Bus bus = robot.own(new RS485Bus(rig.busPort, SerialSettings.eightNoneOne(115_200),
                        BusTiming.defaults().withFrameGap(Duration.ZERO)));
                robot.own(new XVSMMotorModuleLocal(robot, SafetyRig.ROBOT, SafetyRig.MOTOR,
                        new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
                // no pause: the stop is asked as soon as the module is served
                WorldStop.Result result = WorldStop.stop(ops, "ops", "round " + round, List.of(
                        new WorldStop.Target(SafetyRig.ROBOT, SafetyRig.MOTOR, true)), Duration.ofSeconds(30));
                assertTrue(result.complete(), "round " + round + ": " + result);
            }
        }
    }
}
