package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.description.DescriptionLoader;
import robotworld.description.EnvModuleListType;
import robotworld.description.RobotWorldType;
import robotworld.testsupport.ProjectFiles;

/** {@code rwe assemble}: a world from robot files and X10 devices, without editing XML. */
class AssembleCommandTest {

    private static final String ROBOT = ProjectFiles.resolve("docs/examples/parts/caterpillar-robot.xml").toString();
    private static final String ROOM = ProjectFiles.resolve("docs/examples/parts/dim-room.xml").toString();

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    @TempDir
    Path temp;

    private int rwe(String... args) {
        return Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void writesAValidWorldWithAnEnvironmentMadeFromX10Options() throws Exception {
        Path world = temp.resolve("worlds/Lab.xml");
        int code = rwe("assemble", "--robot", ROBOT, "--x10", "A3=appliance:Lamp", "--x10", "b1=lamp",
                "--environment-name", "DimRoom", "--environment-host", "room-pc", "--cm11a-port", "tcp://127.0.0.1:5030",
                "--name", "Lab", "--out", world.toString());
        assertEquals(0, code, err.toString());
        RobotWorldType loaded = DescriptionLoader.loadWorld(world).getRobotWorld();
        assertEquals("Lab", loaded.getWorldName());
        assertEquals("http://localhost:9876/space", loaded.getSpaceURL(), "where rwe space serves by default");
        EnvModuleListType room = loaded.getEnvironmentArray(0);
        assertEquals("DimRoom", room.getEnvironmentName());
        assertEquals("room-pc", room.getHost());
        assertEquals("tcp://127.0.0.1:5030", room.getCOMPort());
        assertEquals("Lamp", room.getX10ModuleArray(0).getName());
        assertEquals("THREE", room.getX10ModuleArray(0).getUnitCode().toString());
        assertEquals("X10ApplianceModule", room.getX10ModuleArray(0).getClass1().toString());
        assertEquals("docs/modules/x10-appliance.md", room.getX10ModuleArray(0).getDocRef(), "from ModuleDescriptions");
        assertEquals("B", room.getX10ModuleArray(1).getHouseCode());
        assertEquals("X10LampModule", room.getX10ModuleArray(1).getClass1().toString());
        assertEquals("CaterpillarRobot", loaded.getRobotDescriptionArray(0).getRobotName());
        assertTrue(out.toString().contains("next: rwe generate " + world + " --viewpoint NAME --out DIR   (NAME: DimRoom,"
                + " CaterpillarRobot, external)"), out.toString());
    }

    @Test
    void environmentFilesAndOptionsMix() throws Exception {
        Path world = temp.resolve("w.xml");
        assertEquals(0, rwe("assemble", "--robot", ROBOT, "--environment", ROOM, "--x10", "C2=lamp",
                "--environment-name", "Hall", "--name", "Both", "--package", "lab.both", "--out", world.toString()),
                err.toString());
        RobotWorldType loaded = DescriptionLoader.loadWorld(world).getRobotWorld();
        assertEquals(2, loaded.sizeOfEnvironmentArray());
        assertEquals("lab.both", loaded.getPackageName());
    }

    @Test
    void aClashBetweenPartsIsReportedInThePartsFile() throws Exception {
        Path copy = Files.copy(Path.of(ROBOT), temp.resolve("copy.xml"));
        assertEquals(1, rwe("assemble", "--robot", ROBOT, "--robot", copy.toString(), "--name", "Twice", "--out",
                temp.resolve("t.xml").toString()));
        assertTrue(err.toString().startsWith(copy + ":4:13: duplicate participant name 'CaterpillarRobot' in this"
                + " world (first used in " + ROBOT + " at line 4)"), err.toString());
        assertFalse(Files.exists(temp.resolve("t.xml")));
    }

    @Test
    void usageErrorsAreOneLineInWords() throws Exception {
        assertEquals(2, rwe("assemble", "--robot", ROBOT, "--x10", "A17=lamp", "--name", "W", "--out", "w.xml"));
        assertEquals("rwe assemble: --x10 A17=lamp: the unit is a number from 1 to 16; got 17\n"
                + "see 'rwe assemble --help'\n", err.toString());
        err.getBuffer().setLength(0);
        assertEquals(2, rwe("assemble", "--robot", ROBOT, "--name", "my world", "--out", "w.xml"));
        assertTrue(err.toString().startsWith("rwe assemble: --name: names may contain only letters, digits and _"),
                err.toString());
        err.getBuffer().setLength(0);
        Path existing = Files.writeString(temp.resolve("keep.xml"), "mine");
        assertEquals(2, rwe("assemble", "--robot", ROBOT, "--name", "W", "--out", existing.toString()));
        assertEquals("mine", Files.readString(existing));
        err.getBuffer().setLength(0);
        assertEquals(1, rwe("assemble", "--robot", temp.resolve("nowhere.xml").toString(), "--name", "W", "--out",
                temp.resolve("n.xml").toString()));
        assertEquals(temp.resolve("nowhere.xml") + ": no such file\n", err.toString());
    }
}
