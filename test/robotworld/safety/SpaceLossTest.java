package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
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

/**
 * Rule 4: a program that serves actuators and cannot reach its space for longer than the command timeout stops
 * them, and says so once in its log; whether the space server is gone (connections refused) or frozen (it accepts
 * and never answers).
 */
class SpaceLossTest {

    private static final Duration START = Duration.ofSeconds(60);
    /** Not about the bus watchdog: a long one, so that only the lost space stops the motors. */
    private static final List<String> NO_WATCHDOG = List.of("-Drwe.watchdog.ms.SafetyBot.Motor=10000");

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
    void aProviderWhoseSpaceServerIsGoneStopsItsMotorsAndSaysSoOnce() throws Exception {
        try (ChildProgram provider = ChildProgram.start(temp, NO_WATCHDOG, SafetyChild.class, "serve", "wait",
                rig.spaceUrl, rig.busPort)) {
            provider.awaitLine("READY", START);
            assertEquals(450, rig.motorSpeed(1));
            rig.space.close();
            eventually("the motors stop", rig::motorsStopped);
            Thread.sleep(2_000); // the outage goes on: nothing more to say
            String output = provider.output();
            assertEquals(1, count(output, "cannot reach its space"), output);
            assertTrue(output.contains("(space-lost: no contact with the space"), output);
            assertTrue(provider.isAlive(), "it keeps serving, waiting for its space");
            assertTrue(rig.motorsStopped());
        }
    }

    @Test
    void aProviderWhoseSpaceServerFreezesStopsItsMotorsAndResumesQuietly() throws Exception {
        TestPeers.requireCommand("kill", "procps");
        try (ChildProgram space = ChildProgram.start(temp, List.of(), Rwe.class, "space", "--port", "0")) {
            space.awaitLine("space server listening on ", START);
            String url = space.output().lines().filter(l -> l.startsWith("space server listening on ")).findFirst()
                    .orElseThrow().substring("space server listening on ".length()).split(" ")[0];
            try (ChildProgram provider = ChildProgram.start(temp, NO_WATCHDOG, SafetyChild.class, "serve", "wait",
                    url, rig.busPort)) {
                provider.awaitLine("READY", START);
                assertEquals(450, rig.motorSpeed(1));
                signal("STOP", space.pid()); // accepts connections, never answers
                eventually("the motors stop", rig::motorsStopped);
                signal("CONT", space.pid());
                eventually("it says it reaches the space again",
                        () -> provider.output().contains("reaches its space"));
                String output = provider.output();
                assertEquals(1, count(output, "cannot reach its space"), output);
                assertTrue(rig.motorsStopped(), "stopped actuators stay stopped until commanded again");
            }
        }
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
