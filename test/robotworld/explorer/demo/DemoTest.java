package robotworld.explorer.demo;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import robotworld.testsupport.ProjectFiles;

/**
 * The whole chapter-5 demo, headless, with a short run: real space server, simulators, exploration, generated
 * projects built by plain Ant, providers and control program in their own JVMs, console monitor.
 */
class DemoTest {

    @TempDir
    Path temp;

    @ParameterizedTest(name = "control program in the {0} viewpoint")
    @EnumSource(Viewpoint.class)
    void theScenarioRunsEndToEndWithRealOutcomes(Viewpoint viewpoint) throws Exception {
        StringWriter text = new StringWriter();
        // the robot-viewpoint run is also recorded, and its recording replayed (see DemoReplayCheck)
        Path recording = viewpoint == Viewpoint.ROBOT ? temp.resolve("demo.mcap") : null;
        DemoOptions options = new DemoOptions(Duration.ofSeconds(12), viewpoint, temp.resolve("demo"), true,
                ProjectFiles.root()).recording(recording);
        DemoSummary summary = new Demo(options, new PrintWriter(text, true)).run();
        String output = text.toString();

        assertTrue(summary.succeeded(), summary.failures() + "\n" + output);
        assertTrue(summary.distanceMoved() > 50, "the robot moved: " + summary.startPose() + " -> "
                + summary.endPose());
        assertTrue(summary.bumps() >= 1, "at least one bump\n" + output);
        assertTrue(summary.lampOnFrames() >= 1 && summary.lampOffFrames() >= 1,
                "X10 on and off frames at the CM11A\n" + output);
        assertTrue(summary.monitorBumps() >= 1, "the monitor saw a bumper contact\n" + output);
        assertTrue(summary.monitorLampOn() >= 1 && summary.monitorLampOff() >= 1, "the monitor saw the lamp\n"
                + output);
        assertTrue(summary.monitorMotor() >= 1, "the monitor saw the motor calls");
        assertTrue(summary.calls().stream().anyMatch(c -> c.name().equals("lamp") && c.calls() >= 2), output);
        // the generated projects stay on disk, built, with the control program in the chosen main class
        Path controlled = viewpoint == Viewpoint.ROBOT
                ? summary.robotProject().resolve("src/chapter5demo/CaterpillarRobot.java")
                : summary.environmentProject().resolve("src/chapter5demo/DimRoom.java");
        assertTrue(Files.readString(controlled).contains("DEMO-STATS"), controlled.toString());
        Path unchanged = viewpoint == Viewpoint.ROBOT
                ? summary.environmentProject().resolve("src/chapter5demo/DimRoom.java")
                : summary.robotProject().resolve("src/chapter5demo/CaterpillarRobot.java");
        assertTrue(!Files.readString(unchanged).contains("DEMO-STATS"), "the provider runs unchanged");
        assertTrue(Files.isDirectory(summary.robotProject().resolve("build/classes")));
        assertTrue(Files.isDirectory(summary.environmentProject().resolve("build/classes")));
        assertTrue(output.contains("[9/9]") && output.contains("result            OK"), output);
        // however the programs ended, the robot's actuators are in their safe state, read at the hardware
        assertTrue(summary.safe(), summary.safeState().toString());
        assertTrue(output.contains("safe state        the robot's actuators are in their safe state"), output);
        assertTrue(summary.stops().stream().anyMatch(stop -> stop.contains("CaterpillarRobot/")
                && stop.contains("motors 1-8 set to 0")), summary.stops().toString());
        if (recording != null) {
            DemoReplayCheck.assertReplaysAsLive(recording, output);
        }
    }

    @Test
    void killingTheControlProgramMidDriveStopsTheRobot() throws Exception {
        // the demo's programs get the demo's safety settings: a command timeout short enough for the stop to come
        // within the run, long enough that a busy machine does not stop the live control program before the kill
        // (the 500 ms default can pass between two of its heartbeats there)
        String commandTimeout = System.getProperty("rwe.command.timeout.ms");
        System.setProperty("rwe.command.timeout.ms", "1500");
        try {
            killAndWatch();
        } finally {
            if (commandTimeout != null) {
                System.setProperty("rwe.command.timeout.ms", commandTimeout);
            } else {
                System.clearProperty("rwe.command.timeout.ms");
            }
        }
    }

    private void killAndWatch() throws Exception {
        StringWriter text = new StringWriter();
        DemoOptions options = new DemoOptions(Duration.ofSeconds(8), Viewpoint.ENVIRONMENT, temp.resolve("demo"), true,
                ProjectFiles.root(), true);
        DemoSummary summary = new Demo(options, new PrintWriter(text, true)).run();
        String output = text.toString();
        assertTrue(summary.succeeded(), summary.failures() + "\n" + output);
        DemoSummary.Kill kill = summary.kill();
        assertTrue(kill.left() > 0 && kill.right() > 0, "killed while driving forward: " + kill);
        assertTrue(kill.millisToZero() >= 0, kill.toString());
        assertTrue(output.contains("KILLED the control program chapter5demo.DimRoom (SIGKILL"), output);
        assertTrue(summary.stops().stream().anyMatch(stop -> stop.contains("commander-silent")),
                summary.stops().toString());
        assertTrue(summary.safe(), output);
    }

    @Test
    void aFailedStepFailsTheDemoAndSaysWhich() {
        StringWriter text = new StringWriter();
        // a home without docs/examples/demo-robot.sim: step 2 cannot start the simulated robot
        DemoOptions options = new DemoOptions(Duration.ofSeconds(1), Viewpoint.ROBOT, temp.resolve("demo"), true,
                temp.resolve("no-home"));
        DemoSummary summary = new Demo(options, new PrintWriter(text, true)).run();
        String output = text.toString();
        assertTrue(!summary.succeeded(), output);
        assertTrue(summary.failures().get(0).startsWith("step 2 "), summary.failures().toString());
        assertTrue(output.contains("[2/9]") && output.contains("FAILED") && !output.contains("[3/9]"), output);
    }
}
