package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import robotworld.explorer.cli.Rwe;
import robotworld.testsupport.TestPeers;
import robotworld.xvsm.ActuatorStoppedException;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * Rule 4: a program that serves actuators and cannot reach its space for longer than the command timeout stops
 * them and says so once in its log; whether the space server is gone (connections refused), killed with SIGKILL, or
 * frozen (it accepts and never answers). By default it stops every engaged actuator and holds them all in their safe
 * state until the space answers again (nobody elsewhere could stop what its own program would start meanwhile): its
 * own commands are refused and it is told. With {@code rwe.space.loss.stops=remote} only what a program elsewhere
 * commanded through the space is stopped.
 *
 * <p>The serving program runs in a JVM of its own ({@code SafetyChild serve winch|drive}): it drives the wheels
 * (Motor) itself at 0.45 and serves the Winch, which this test commands through the space as a remote commander.
 */
class SpaceLossTest {

    private static final Duration START = Duration.ofSeconds(60);
    /**
     * Not about the bus watchdog: a long one, so that only the lost space stops a motor. A command timeout of 3 s
     * (the rule's delay): a busy machine that holds a live commander's heartbeats back for half a second must not
     * stop the winch for a silent commander (rule 3) before the space is gone.
     */
    private static final List<String> PROVIDER = List.of("-Drwe.watchdog.ms=10000", "-Drwe.command.timeout.ms=3000");

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
    void aProviderWhoseSpaceServerIsGoneStopsEveryActuatorAndSaysSoOnce() throws Exception {
        try (ChildProgram provider = ChildProgram.start(temp, PROVIDER, SafetyChild.class, "serve", "winch",
                rig.spaceUrl, rig.busPort);
             XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop")) {
            provider.awaitLine("READY", START);
            XVSMMotorModuleRemote winch = winch(laptop);
            winch.setMotor(1, 0.3);
            assertEquals(300, rig.winchSpeed(1));
            assertEquals(450, rig.motorSpeed(1));
            rig.space.close();
            eventually("the winch, commanded through the space, stops", () -> rig.winchSpeed(1) == 0);
            eventually("the wheels its own program drives stop too", () -> rig.motorSpeed(1) == 0
                    && rig.motorSpeed(2) == 0);
            Thread.sleep(2_000); // the outage goes on: nothing more to say, nothing more to stop
            String output = provider.output();
            assertEquals(1, count(output, "cannot reach its space"), output);
            assertTrue(output.contains("Winch stopped") && output.contains("Motor stopped")
                    && output.contains("(space-lost: no contact with the space"), output);
            assertTrue(provider.isAlive(), "it keeps serving, waiting for its space");
            assertEquals(0, rig.winchSpeed(1));
            assertEquals(0, rig.motorSpeed(1));
        }
    }

    @Test
    void aProviderWhoseSpaceServerProcessIsKilledStopsItsActuators() throws Exception {
        TestPeers.requireCommand("kill", "procps");
        try (ChildProgram space = spaceServer();
             ChildProgram provider = ChildProgram.start(temp, PROVIDER, SafetyChild.class, "serve", "winch",
                     url(space), rig.busPort);
             XVSMRuntime laptop = XVSMRuntime.connect(url(space), "laptop")) {
            provider.awaitLine("READY", START);
            winch(laptop).setMotor(1, -0.6);
            assertEquals(-600, rig.winchSpeed(1));
            signal("KILL", space.pid()); // no goodbye: its connections just break
            space.awaitExit(START);
            eventually("the winch stops", () -> rig.winchSpeed(1) == 0);
            eventually("the wheels stop", () -> rig.motorSpeed(1) == 0 && rig.motorSpeed(2) == 0);
            eventually("its log says why", () -> provider.output().contains("(space-lost: no contact with the space"));
        }
    }

    @Test
    void whileItsSpaceIsFrozenAProviderHoldsItsActuatorsAndRefusesItsOwnCommandsThenResumes() throws Exception {
        TestPeers.requireCommand("kill", "procps");
        try (ChildProgram space = spaceServer();
             ChildProgram provider = ChildProgram.start(temp, PROVIDER, SafetyChild.class, "serve", "drive",
                     url(space), rig.busPort);
             XVSMRuntime laptop = XVSMRuntime.connect(url(space), "laptop")) {
            provider.awaitLine("READY", START);
            XVSMMotorModuleRemote winch = winch(laptop);
            winch.setMotor(1, 0.3);
            assertEquals(300, rig.winchSpeed(1));
            signal("STOP", space.pid()); // accepts connections, never answers
            eventually("the winch stops", () -> rig.winchSpeed(1) == 0);
            eventually("the wheels stop", () -> rig.motorSpeed(1) == 0 && rig.motorSpeed(2) == 0);
            eventually("its own program is told", () -> provider.output().contains("REFUSED"));
            for (int i = 0; i < 20; i++) { // its control loop commands 0.45 every 50 ms: held, nothing moves
                assertEquals(0, rig.motorSpeed(1), "held while the space is frozen\n" + provider.output());
                Thread.sleep(50);
            }
            String refused = provider.output().lines().filter(l -> l.startsWith("REFUSED")).findFirst().orElseThrow();
            assertTrue(refused.contains("space-lost") && refused.contains("takes commands again once"), refused);
            signal("CONT", space.pid());
            eventually("it says it reaches the space again", () -> provider.output().contains("reaches its space"));
            eventually("its own commands are carried out again", () -> provider.output().contains("DRIVING")
                    && rig.motorSpeed(1) == 450);
            String output = provider.output();
            assertEquals(1, count(output, "cannot reach its space"), output);
            assertEquals(0, rig.winchSpeed(1), "stopped actuators stay stopped until commanded again");
            assertThrows(ActuatorStoppedException.class, () -> winch.setMotor(1, 0.3),
                    "the remote commander is told on its next call");
            winch.setMotor(1, 0.3);
            assertEquals(300, rig.winchSpeed(1), "and obeyed on the call after it");
        }
    }

    @Test
    void withSpaceLossStoppingOnlyRemoteCommandsTheProgramsOwnWheelsKeepRunning() throws Exception {
        List<String> remoteOnly = new java.util.ArrayList<>(PROVIDER);
        remoteOnly.add("-Drwe.space.loss.stops=remote");
        try (ChildProgram provider = ChildProgram.start(temp, remoteOnly, SafetyChild.class, "serve", "winch",
                rig.spaceUrl, rig.busPort);
             XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop")) {
            provider.awaitLine("READY", START);
            winch(laptop).setMotor(1, 0.3);
            assertEquals(300, rig.winchSpeed(1));
            rig.space.close();
            eventually("the winch, commanded through the space, stops", () -> rig.winchSpeed(1) == 0);
            Thread.sleep(1_000);
            String output = provider.output();
            assertTrue(output.contains("the actuators commanded through it are stopped"), output);
            assertEquals(450, rig.motorSpeed(1), "what only its own program drives keeps running\n" + output);
            assertEquals(450, rig.motorSpeed(2));
        }
    }

    private ChildProgram spaceServer() throws Exception {
        ChildProgram space = ChildProgram.start(temp, List.of(), Rwe.class, "space", "--port", "0");
        space.awaitLine("space server listening on ", START);
        return space;
    }

    private static String url(ChildProgram space) {
        return space.output().lines().filter(l -> l.startsWith("space server listening on ")).findFirst()
                .orElseThrow().substring("space server listening on ".length()).split(" ")[0];
    }

    private static XVSMMotorModuleRemote winch(XVSMRuntime laptop) {
        XVSMMotorModuleRemote winch = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT, SafetyRig.WINCH));
        winch.setCallTimeout(Duration.ofSeconds(30));
        return winch;
    }

    private static int count(String text, String part) {
        int count = 0;
        for (int at = text.indexOf(part); at >= 0; at = text.indexOf(part, at + 1)) {
            count++;
        }
        return count;
    }

    private static void signal(String signal, long pid) throws Exception {
        Process kill = new ProcessBuilder("kill", "-" + signal, Long.toString(pid)).inheritIO().start();
        assertEquals(0, kill.waitFor(), "kill -" + signal);
    }
}
