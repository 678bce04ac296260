package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.testsupport.ProjectFiles;

class SimulateRobotCommandTest {

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    @TempDir
    Path folder;

    private int rwe(String... args) {
        return Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void servesTheExampleRobotUntilItsTimeIsUp() throws Exception {
        String config = ProjectFiles.resolve("docs/examples/simulated-robot.sim").toString();
        CompletableFuture<Integer> run = CompletableFuture.supplyAsync(() -> rwe("simulate", "robot", "--config", config,
                "--port", "tcp://127.0.0.1:0", "--timing", "fast", "--for", "1.5"));
        Pattern served = Pattern.compile("serving the bus on (tcp://127\\.0\\.0\\.1:\\d+)");
        long deadline = System.nanoTime() + 5_000_000_000L;
        Matcher matcher = served.matcher("");
        while (!(matcher = served.matcher(out.toString())).find()) {
            assertTrue(System.nanoTime() < deadline && !run.isDone(), "not served: " + out + err);
            Thread.sleep(10);
        }
        try (RS485Bus bus = new RS485Bus(matcher.group(1), SerialSettings.eightNoneOne(115_200), BusTiming.defaults())) {
            assertEquals("15B63B2", bus.identify(2).productCode());
        }
        assertEquals(0, run.get(5, TimeUnit.SECONDS), err.toString());
        assertTrue(out.toString().contains("simulated robot 'CaterpillarRobot': MotorModule at 1, BumperModule at 2, "
                + "ServoModule at 3, IRDistanceModule at 4; 115200 baud, fast timing"), out.toString());
        assertTrue(out.toString().contains("robot at (600.0, 1000.0) heading 0.0"), out.toString());
        assertTrue(out.toString().contains("[   1 s] at (600, 1000) heading 0°, tracks L +0.00 R +0.00, free, 0 bumps"),
                "a status line every second: " + out);
    }

    @Test
    void publishesTheGroundTruthToASpaceAndKeepsQuietWhenAsked() throws Exception {
        try (robotworld.space.EmbeddedSpace data = robotworld.space.EmbeddedSpace.open();
             robotworld.space.server.SpaceServer server = robotworld.space.server.SpaceServer.start(data,
                     robotworld.space.server.SpaceServer.Options.defaults().port(0).stopGraceMillis(200))) {
            String config = ProjectFiles.resolve("docs/examples/simulated-robot.sim").toString();
            assertEquals(0, rwe("simulate", "robot", "--config", config, "--port", "tcp://127.0.0.1:0", "--for", "1.3",
                    "--quiet", "--space", server.uri().toString(), "--participant", "Robbie"), err.toString());
            assertTrue(out.toString().contains("publishing its ground truth to " + server.uri()
                    + " as RobbieGROUNDTRUTH"), out.toString());
            assertTrue(!out.toString().contains("[   1 s]"), "--quiet: no status line\n" + out);
            var frames = data.read(data.lookupContainer("RobbieGROUNDTRUTH"), robotworld.space.Timeout.TRY_ONCE);
            assertEquals("Robbie", robotworld.observe.GroundTruthTuples.decode(frames.get(0)).robot());
        }
    }

    @Test
    void aBadConfigurationListsItsProblems() throws Exception {
        Path config = folder.resolve("bad.xml");
        Files.writeString(config, "<SimulatedRobot><World width=\"10\"/></SimulatedRobot>");
        assertEquals(1, rwe("simulate", "robot", "--config", config.toString(), "--port", "tcp://127.0.0.1:0"));
        assertTrue(err.toString().contains(config + ": <World>: attribute 'height' is required"), err.toString());
        assertTrue(err.toString().contains(config + ": <Body x=... y=...> is missing"), err.toString());
    }

    @Test
    void badOptionsAreUsageErrors() {
        String config = ProjectFiles.resolve("docs/examples/simulated-robot.sim").toString();
        assertEquals(2, rwe("simulate", "robot", "--config", config, "--timing", "slow"));
        assertTrue(err.toString().contains("timing 'slow' is neither fast nor real"), err.toString());
        assertEquals(2, rwe("simulate", "robot", "--config", config, "--port", "udp://x:1"));
        assertEquals(2, rwe("simulate", "robot"));
    }

    @Test
    void simulateWithoutADeviceNamesBoth() {
        assertEquals(2, rwe("simulate"));
        assertTrue(err.toString().contains("cm11a or robot"), err.toString());
    }
}
