package robotworld.explorer.demo;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;

/**
 * The chapter-5 demo on a clustered space ({@code ./antw demo -Dcluster=3}): three {@code rwe space --cluster}
 * processes, the programs given all three servers, and the server every program talks to first killed with SIGKILL
 * halfway through the run. The run must complete with the same real outcomes as on one server, and the world must
 * go on after the kill.
 */
class ClusteredDemoTest {

    @TempDir
    Path temp;

    @Test
    void theDemoCompletesWhenTheSpaceServerItTalksToIsKilled() {
        StringWriter text = new StringWriter();
        DemoOptions options = new DemoOptions(Duration.ofSeconds(16), Viewpoint.ENVIRONMENT, temp.resolve("demo"),
                true, ProjectFiles.root()).clustered(3);
        DemoSummary summary = new Demo(options, new PrintWriter(text, true)).run();
        String output = text.toString();

        assertTrue(summary.succeeded(), summary.failures() + "\n" + output);
        assertTrue(output.contains("starting 3 clustered space servers"), output);
        DemoSummary.MemberKill kill = summary.memberKill();
        assertNotNull(kill, "a member was killed\n" + output);
        assertTrue(output.contains("killed the space server " + kill.url() + " (pid "), output);
        // the robot was still driving under its remote control program after the kill, and the lamp still switched
        assertTrue(kill.distanceAfter() > 20 || kill.bumpsAfter() >= 1, "the world went on after the kill: " + kill
                + "\n" + output);
        assertTrue(summary.bumps() >= 1, "at least one bump\n" + output);
        assertTrue(summary.lampOnFrames() >= 1 && summary.lampOffFrames() >= 1, "the lamp switched\n" + output);
        assertTrue(summary.monitorMotor() >= 1 && summary.monitorBumps() >= 1, "the monitor saw the robot\n" + output);
        assertTrue(summary.safe(), summary.safeState().toString());
        assertTrue(output.contains("member killed     " + kill.url()) && output.contains("result            OK"),
                output);
    }
}
