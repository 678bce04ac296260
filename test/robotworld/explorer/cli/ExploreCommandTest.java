package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.description.DescriptionLoader;
import robotworld.description.ModuleListType;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;

class ExploreCommandTest {

    private static final String ROBOT = """
            <SimulatedRobot name="CliBot">
              <World width="2000" height="1000"/>
              <Body x="500" y="500"/>
              <Motor address="1" left="1" right="2"/>
              <Bumper address="2"/>
              <Bumper address="3" nodeId="NOPE"/>
              <Servo address="4" refuseWith="2"/>
            </SimulatedRobot>""";

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();
    private SimulatedRobot robot;
    private String port;

    @TempDir
    Path folder;

    @BeforeEach
    void start() throws Exception {
        robot = SimulatedRobot.create(SimRobotConfigReader.parse(ROBOT, "cli robot"));
        port = robot.serve("tcp://127.0.0.1:0");
    }

    @AfterEach
    void stop() {
        robot.close();
    }

    private int rwe(String... args) {
        return Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void writesTheDescriptionListsProblemsAndShowsProgress() throws Exception {
        Path file = folder.resolve("robots/CliBot.xml");
        // generous timing, as for a slow link: the progress shows each module as its probe finds it, and on a busy
        // machine a simulated module may answer later than the default 8 ms scan allowance
        int code = rwe("explore", "--port", port, "--name", "CliBot", "--out", file.toString(), "--to", "10",
                "--host", "robot-pc", "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString(),
                "--scan-allowance", "500", "--timeout", "500");
        assertEquals(0, code, err.toString());

        ModuleListType described = DescriptionLoader.loadRobot(file).getRobotDescription();
        assertEquals("CliBot", described.getRobotName());
        assertEquals("robot-pc", described.getHost());
        assertEquals(port, described.getCOMPort());
        assertEquals(2, described.sizeOfModuleArray());

        String stdout = out.toString();
        assertTrue(stdout.contains("found   address 1: MotorModule 'Motor-Controller' (NodeID 15B63A4, version 1.0)"),
                stdout);
        assertTrue(stdout.contains("skipped address 3: unknown node id: NodeID 'NOPE' has no description"), stdout);
        assertTrue(stdout.contains("skipped address 4: exception response: address 4 on " + port
                + " refused read device identification (0x2B) with Modbus exception 2 (illegal data address)"), stdout);
        assertTrue(stdout.contains("2 modules found, 2 addresses skipped, 10 addresses in "), stdout);
        assertTrue(stdout.contains("wrote " + file + ": robot 'CliBot' with 2 modules"), stdout);

        String stderr = err.toString();
        assertTrue(stderr.contains("exploring RS485Bus " + port), stderr);
        assertTrue(stderr.contains("[##############################]  10/10  address  10  2 found"), stderr);
        assertTrue(stderr.contains("\r"), "the bar is redrawn in place");
        assertTrue(stderr.contains("skipped address 4"), "problems are listed as they happen: " + stderr);
    }

    @Test
    void noModuleFoundExitsOneAndWritesNothing() {
        Path file = folder.resolve("none.xml");
        int code = rwe("explore", "--port", port, "--name", "Nobody", "--out", file.toString(), "--from", "20",
                "--to", "25", "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString());
        assertEquals(1, code);
        assertTrue(err.toString().contains("rwe explore: no module answered on " + port + "; nothing written.\n"
                + "Check that the robot is switched on"), err.toString());
        assertFalse(Files.exists(file));
    }

    @Test
    void usageErrorsExitTwo() {
        assertEquals(2, rwe("explore", "--port", port, "--name", "X"));
        assertTrue(err.toString().contains("rwe explore: missing option '--out=FILE'\nsee 'rwe explore --help'"),
                err.toString());
        assertEquals(2, rwe("explore", "--port", "ftp://host:1", "--name", "X", "--out", "x.xml",
                "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString()));
        assertTrue(err.toString().contains("unsupported port scheme 'ftp'"), err.toString());
        assertEquals(2, rwe("explore", "--port", port, "--name", "X", "--out", "x.xml", "--from", "0",
                "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString()));
        assertEquals(2, rwe("explore", "--port", port, "--name", "X", "--out", "x.xml",
                "--descriptions", folder.resolve("missing").toString()));
    }

    @Test
    void aBadRobotNameIsAUsageErrorInWords() {
        assertEquals(2, rwe("explore", "--port", port, "--name", "my robot", "--out", folder.resolve("a.xml").toString(),
                "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString()));
        assertEquals("rwe explore: --name: names may contain only letters, digits and _, and may not start with a digit;"
                + " got 'my robot'\nsee 'rwe explore --help'\n", err.toString());
        err.getBuffer().setLength(0);
        assertEquals(2, rwe("explore", "--port", port, "--name", "R", "--out", "x.xml", "--from", "t"));
        assertEquals("rwe explore: --from: 't' is not a number\nsee 'rwe explore --help'\n", err.toString());
    }

    @Test
    void anUnreachablePortFailsWithTheFix() {
        robot.close();
        assertEquals(1, rwe("explore", "--port", port, "--name", "Gone", "--out", folder.resolve("b.xml").toString(),
                "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString()));
        assertTrue(err.toString().contains("rwe explore: nothing answers at " + port + " (connection refused).\n"
                + "Start the simulator or serial bridge there"), err.toString());
        assertTrue(err.toString().contains("or choose the port with --port PORT."), err.toString());
        assertFalse(err.toString().contains("\tat "), err.toString());
    }

    /** Like generate, explore refuses to overwrite a file unless told to. */
    @Test
    void anExistingDescriptionIsKeptWithoutForce() throws Exception {
        Path file = Files.writeString(folder.resolve("CliBot.xml"), "my edits");
        assertEquals(2, rwe("explore", "--port", port, "--name", "CliBot", "--out", file.toString(), "--to", "2",
                "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString()));
        assertTrue(err.toString().contains(file + " exists; choose another --out or add --force to replace it"),
                err.toString());
        assertEquals("my edits", Files.readString(file));
        assertEquals(0, rwe("explore", "--port", port, "--name", "CliBot", "--out", file.toString(), "--to", "2",
                "--force", "--descriptions", ProjectFiles.resolve("ModuleDescriptions").toString()), err.toString());
        assertEquals("CliBot", DescriptionLoader.loadRobot(file).getRobotDescription().getRobotName());
    }
}
