package robotworld.description;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;

/** The usage scenario of thesis 3.3.1: robot and environment files assembled into one RobotWorld. */
class RobotWorldAssemblerTest {

    private static final Path ROBOT = ProjectFiles.resolve("docs/examples/parts/caterpillar-robot.xml");
    private static final Path ROOM = ProjectFiles.resolve("docs/examples/parts/dim-room.xml");
    private static final Path CHAPTER5 = ProjectFiles.resolve("docs/examples/chapter5-world.xml");

    @TempDir
    Path temp;

    @Test
    void assemblesTheChapter5WorldFromItsParts() throws Exception {
        RobotWorldDocument assembled = new RobotWorldAssembler("Chapter5World")
                .communicationType("xvsm").packageName("chapter5").spaceUrl("http://localhost:9876/space")
                .addEnvironment(ROOM).addRobot(ROBOT).assemble();
        RobotWorldType expected = DescriptionLoader.loadWorld(CHAPTER5).getRobotWorld();
        assertTrue(expected.valueEquals(assembled.getRobotWorld()),
                "assembled world differs from the example:\n" + assembled);
    }

    @Test
    void writtenWorldLoadsBackValid() throws Exception {
        RobotWorldDocument assembled = new RobotWorldAssembler("Written").addRobot(ROBOT).assemble();
        Path file = temp.resolve("out/world.xml");
        RobotWorldAssembler.write(assembled, file);
        RobotWorldType reloaded = DescriptionLoader.loadWorld(file).getRobotWorld();
        assertEquals("Written", reloaded.getWorldName());
        assertEquals("CaterpillarRobot", reloaded.getRobotDescriptionArray(0).getRobotName());
        assertTrue(Files.readString(file).contains("xmlns=\"urn:robotworld:description\""));
    }

    @Test
    void sameRobotTwiceIsADuplicateParticipant() {
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> new RobotWorldAssembler("Twice").addRobot(ROBOT).addRobot(ROBOT).assemble());
        assertTrue(thrown.getMessage().contains("duplicate participant name 'CaterpillarRobot'"), thrown.getMessage());
    }

    @Test
    void errorsOfEveryPartAreReportedWithTheirFiles() throws Exception {
        Path badRobot = Files.writeString(temp.resolve("bad-robot.xml"),
                Files.readString(ROBOT).replace("<NodeNumber>2</NodeNumber>", "<NodeNumber>999</NodeNumber>"));
        Path badRoom = Files.writeString(temp.resolve("bad-room.xml"),
                Files.readString(ROOM).replace("<HouseCode>A</HouseCode>", "<HouseCode>X</HouseCode>"));
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> new RobotWorldAssembler("Broken").addEnvironment(badRoom).addRobot(badRobot).assemble());
        assertEquals(2, thrown.errors().size(), thrown.getMessage());
        assertTrue(thrown.errors().get(0).toString().startsWith(badRoom + ":"), thrown.getMessage());
        assertTrue(thrown.errors().get(1).toString().startsWith(badRobot + ":"), thrown.getMessage());
    }

    @Test
    void worldWithoutRobotOrWithUnknownCommunicationTypeIsRefused() {
        DescriptionException noRobot = assertThrows(DescriptionException.class,
                () -> new RobotWorldAssembler("Empty").addEnvironment(ROOM).assemble());
        assertTrue(noRobot.getMessage().contains("at least one robot"));
        DescriptionException badType = assertThrows(DescriptionException.class,
                () -> new RobotWorldAssembler("Odd").communicationType("corba").addRobot(ROBOT).assemble());
        assertTrue(badType.getMessage().contains("unknown communication type 'corba'"));
    }

    @Test
    void invalidWorldNameIsCaughtByTheSchema() {
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> new RobotWorldAssembler("My World").addRobot(ROBOT).assemble());
        assertTrue(thrown.getMessage().contains("'My World'"), thrown.getMessage());
    }
}
