package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.safety.SafetyRig.eventually;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.space.Capi;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;
import robotworld.testsupport.TestPeers;
import robotworld.xvsm.CallTuple;
import robotworld.xvsm.XVSMModule;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * Rule 3: an actuator commanded from another program keeps its last command only while that program is alive;
 * the serving program stops it when the commander has been silent for the command timeout, or ended, and tells
 * the commander on its next call.
 */
class RemoteCommanderTest {

    private static final Duration START = Duration.ofSeconds(60);
    /**
     * The command timeout of the tests about it. A live commander's heartbeats (every 100 ms) keep its motors
     * running; with the default 500 ms, a busy machine that holds them back half a second stops a commander that is
     * alive, so these tests use 3 s: a silent commander is still stopped, only later.
     */
    private static final Duration COMMAND_TIMEOUT = Duration.ofSeconds(3);

    @TempDir
    Path temp;

    private SafetyRig rig;
    private XVSMRuntime provider;
    private XVSMMotorModuleLocal motor;

    @BeforeEach
    void startRigAndProvider() throws Exception {
        rig = SafetyRig.start();
        provider = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
        // not about the bus watchdog: a long one, so a busy machine does not stop the motors for another reason;
        // about the command timeout: one a busy machine does not run out while the commander lives
        provider.safety().describe(SafetyRig.ROBOT, SafetyRig.MOTOR, new ModuleSafety(null, 10_000, null));
        provider.safety().setDefaultCommandTimeout(COMMAND_TIMEOUT);
        RS485Bus bus = provider.own(new RS485Bus(rig.busPort, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO)));
        motor = provider.own(new XVSMMotorModuleLocal(provider, SafetyRig.ROBOT, SafetyRig.MOTOR,
                new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
    }

    @AfterEach
    void stop() {
        provider.close();
        rig.close();
    }

    @Test
    void aCommanderKilledWithSigkillHasItsMotorsStopped() throws Exception {
        try (ChildProgram commander = ChildProgram.start(temp, List.of(), SafetyChild.class, "command",
                rig.spaceUrl, "0.4")) {
            commander.awaitLine("READY", START);
            String commanderId = readyId(commander);
            assertEquals(400, rig.motorSpeed(1));
            commander.kill();
            eventually("the motors stop", rig::motorsStopped);
            StopRecord stop = lastStop(StopCause.COMMANDER_SILENT).orElseThrow();
            assertEquals(commanderId, stop.commander());
            assertTrue(stop.reason().startsWith(commanderId + " silent for "), stop.reason());
            assertEquals("motors 1-8 set to 0", stop.action());
        }
    }

    @Test
    void aCommanderThatLosesItsSpaceHasItsMotorsStopped() throws Exception {
        XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop");
        XVSMMotorModuleRemote remote = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT, SafetyRig.MOTOR));
        remote.setMotor(2, -0.3);
        assertEquals(-300, rig.motorSpeed(2));
        laptop.space().close(); // no more heartbeats, no more calls: as a cable pulled out of the laptop
        eventually("the motors stop", rig::motorsStopped);
        assertEquals(laptop.programId(), lastStop(StopCause.COMMANDER_SILENT).orElseThrow().commander());
        laptop.close();
    }

    @Test
    void aCommanderThatEndsHasItsMotorsStoppedWithoutWaitingForTheTimeout() throws Exception {
        provider.safety().guards().get(0).setCommandTimeout(Duration.ofMinutes(10));
        XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop");
        XVSMMotorModuleRemote remote = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT, SafetyRig.MOTOR));
        remote.setMotor(1, 0.5);
        laptop.close(); // its last heartbeat says it ended
        eventually("the motors stop", rig::motorsStopped);
        assertEquals(laptop.programId(), lastStop(StopCause.COMMANDER_ENDED).orElseThrow().commander());
    }

    @Test
    void aLiveCommanderThatIsQuietKeepsItsMotorsRunning() throws Exception {
        try (XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop")) {
            XVSMMotorModuleRemote remote = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT,
                    SafetyRig.MOTOR));
            remote.setMotor(1, 0.2);
            // no calls for more than twice the command timeout: its heartbeats keep it
            Thread.sleep(2 * COMMAND_TIMEOUT.toMillis() + 500);
            assertEquals(200, rig.motorSpeed(1));
            assertTrue(provider.safety().recentStops().isEmpty(), provider.safety().recentStops().toString());
        }
    }

    @Test
    void aCommanderThatLeftItsMotorsAtRestIsNotStoppedForIt() throws Exception {
        XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop");
        XVSMMotorModuleRemote remote = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT, SafetyRig.MOTOR));
        remote.setMotor(1, 0.2);
        remote.setMotor(1, 0);
        laptop.space().close();
        Thread.sleep(1_500);
        assertTrue(provider.safety().recentStops().isEmpty(), "nothing to stop");
        laptop.close();
    }

    @Test
    void aFrozenCommanderIsToldOnItsNextCallThatItsMotorsWereStopped() throws Exception {
        TestPeers.requireCommand("kill", "procps");
        Path go = temp.resolve("go");
        try (ChildProgram commander = ChildProgram.start(temp, List.of(), SafetyChild.class, "command",
                rig.spaceUrl, "0.4", go.toString())) {
            commander.awaitLine("READY", START);
            signal("STOP", commander.pid()); // frozen, as a laptop whose lid was closed
            eventually("the motors stop", rig::motorsStopped);
            signal("CONT", commander.pid());
            Files.createFile(go);
            commander.awaitLine("AGAIN", START);
            String output = commander.output();
            assertTrue(output.contains("TOLD SafetyBot/Motor setMotor refused: the actuator was stopped at"), output);
            assertTrue(output.contains("commander-silent"), output);
            assertEquals(400, rig.motorSpeed(1), "commanded again, it moves");
        }
    }

    @Test
    void aCommanderWithoutHeartbeatsIsToldThroughTheDocumentedTupleLayout() throws Exception {
        provider.safety().guards().get(0).setCommandTimeout(Duration.ofMillis(200));
        try (Capi ghost = RemoteSpace.open(rig.space.uri())) {
            String requests = XVSMModule.requestContainerName(SafetyRig.ROBOT, SafetyRig.MOTOR);
            String answers = XVSMModule.answerContainerName(SafetyRig.ROBOT, SafetyRig.MOTOR);
            // a program that commands by hand, without a runtime, and never sends a heartbeat
            ghost.write(ghost.lookupContainer(requests), Timeout.TRY_ONCE,
                    CallTuple.of("ghost#r1.1", "setMotor", 1, 600).toTuple());
            List<Entry> done = ghost.take(ghost.lookupContainer(answers), Timeout.ofMillis(30_000),
                    Selector.key("ghost#r1.1"));
            // carried out (the motor's speed itself may already be back at 0: 200 ms pass quickly on a busy machine)
            assertTrue(!CallTuple.parse(done.get(0)).is("ERROR"), done.toString());
            eventually("stopped after 200 ms without a call", rig::motorsStopped);
            ghost.write(ghost.lookupContainer(requests), Timeout.TRY_ONCE,
                    CallTuple.of("ghost#r1.2", "setMotor", 1, 600).toTuple());
            List<Entry> answer = ghost.take(ghost.lookupContainer(answers), Timeout.ofMillis(30_000),
                    Selector.key("ghost#r1.2"));
            CallTuple refused = CallTuple.parse(answer.get(0));
            assertTrue(refused.is("ERROR"), refused.toString());
            assertEquals("stopped", refused.tupleAt(1).stringAt(0), refused.toString());
            assertEquals(0, rig.motorSpeed(1), "the refused command was not carried out");
            assertTrue(Item.of(answer.get(0)).entry().toString().contains("commander-silent"), refused.toString());
        }
    }

    private Optional<StopRecord> lastStop(StopCause cause) {
        eventually("a stop record " + cause.wireName(), () -> provider.safety().recentStops().stream()
                .anyMatch(stop -> stop.cause() == cause));
        List<StopRecord> stops = provider.safety().recentStops();
        for (int i = stops.size() - 1; i >= 0; i--) {
            if (stops.get(i).cause() == cause) {
                return Optional.of(stops.get(i));
            }
        }
        return Optional.empty();
    }

    private static String readyId(ChildProgram child) {
        return child.output().lines().filter(line -> line.startsWith("READY ")).findFirst().orElseThrow()
                .substring("READY ".length()).strip();
    }

    private static void signal(String signal, long pid) throws Exception {
        Process kill = new ProcessBuilder("kill", "-" + signal, Long.toString(pid)).inheritIO().start();
        assertEquals(0, kill.waitFor(), "kill -" + signal);
    }
}
