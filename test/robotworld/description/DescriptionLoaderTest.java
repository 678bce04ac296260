package robotworld.description;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;

class DescriptionLoaderTest {

    private static final Path CHAPTER5 = ProjectFiles.resolve("docs/examples/chapter5-world.xml");

    @TempDir
    Path temp;

    @Test
    void loadsFromFileStreamAndString() throws Exception {
        String xml = Files.readString(CHAPTER5);
        assertEquals("Chapter5World", DescriptionLoader.loadWorld(CHAPTER5).getRobotWorld().getWorldName());
        try (InputStream in = new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8))) {
            assertEquals("Chapter5World", DescriptionLoader.loadWorld(in, "stream").getRobotWorld().getWorldName());
        }
        assertEquals("Chapter5World",
                DescriptionLoader.loadWorldFromString(xml, "string").getRobotWorld().getWorldName());
    }

    @Test
    void errorsNameTheSourceGivenForStringsAndStreams() {
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorldFromString("<RobotWorld xmlns='urn:robotworld:description'>"
                        + "\n<WorldName>W</WorldName>\n<CommunicationType>tcp</CommunicationType></RobotWorld>",
                        "my-world"));
        assertTrue(thrown.errors().get(0).toString().startsWith("my-world:3:"), thrown.getMessage());
    }

    @Test
    void externalEntityIsNeverRead() throws Exception {
        Path secret = Files.writeString(temp.resolve("secret.txt"), "TOP-SECRET-CONTENT");
        String xml = "<?xml version='1.0'?>\n<!DOCTYPE RobotWorld [<!ENTITY s SYSTEM '" + secret.toUri() + "'>]>\n"
                + "<RobotWorld xmlns='urn:robotworld:description'><WorldName>&s;</WorldName></RobotWorld>";
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorldFromString(xml, "xxe"));
        assertFalse(thrown.getMessage().contains("TOP-SECRET"), thrown.getMessage());
        assertTrue(thrown.getMessage().contains("DOCTYPE"), thrown.getMessage());
        assertEquals(2, thrown.errors().get(0).line());
    }

    @Test
    void oversizedInputIsRefusedBeforeParsing() throws Exception {
        Path huge = temp.resolve("huge.xml");
        byte[] filler = new byte[(int) DescriptionLoader.MAX_BYTES + 1];
        java.util.Arrays.fill(filler, (byte) ' ');
        Files.write(huge, filler);
        DescriptionException thrown = assertThrows(DescriptionException.class, () -> DescriptionLoader.loadWorld(huge));
        assertTrue(thrown.getMessage().startsWith(huge + ":1:1: ") && thrown.getMessage().contains("at most 4 MiB"),
                thrown.getMessage());
        assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(new ByteArrayInputStream(filler), "stream"));
    }

    @Test
    void missingFileIsAnErrorNotAnException() {
        Path missing = temp.resolve("nowhere.xml");
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(missing));
        assertEquals(missing + ": no such file", thrown.getMessage());
    }

    @Test
    void wrongKindOfDescriptionIsNamed() {
        Path robot = ProjectFiles.resolve("docs/examples/parts/caterpillar-robot.xml");
        DescriptionException thrown = assertThrows(DescriptionException.class, () -> DescriptionLoader.loadWorld(robot));
        assertTrue(thrown.getMessage().contains("expected a RobotWorld description but found <RobotDescription>"),
                thrown.getMessage());
    }

    @Test
    void anyKindIsRecognised() throws Exception {
        assertEquals(DescriptionKind.ROBOT, DescriptionLoader.kindOf(
                DescriptionLoader.load(ProjectFiles.resolve("docs/examples/parts/caterpillar-robot.xml"), null)));
        assertEquals(DescriptionKind.ENVIRONMENT, DescriptionLoader.kindOf(
                DescriptionLoader.load(ProjectFiles.resolve("docs/examples/parts/dim-room.xml"), null)));
        assertEquals(DescriptionKind.MODULE, DescriptionLoader.kindOf(
                DescriptionLoader.load(ProjectFiles.resolve("ModuleDescriptions/15B63A4.xml"), null)));
        assertEquals(DescriptionKind.ROBOT_WORLD, DescriptionLoader.kindOf(DescriptionLoader.load(CHAPTER5, null)));
    }

    @Test
    void environmentWithBusModulesIsValidWhenItNamesPortAndBusClass() throws Exception {
        String xml = """
                <Environment xmlns="urn:robotworld:description">
                  <EnvironmentName>Hall</EnvironmentName>
                  <Host>hall-pc</Host>
                  <COMPort>tcp://127.0.0.1:4000</COMPort>
                  <BusPort>/dev/ttyUSB1</BusPort>
                  <TalkToBusClass>RS485Bus</TalkToBusClass>
                  <Module>
                    <Name>Door-Servo</Name><NodeID>15B63A1</NodeID><NodeNumber>3</NodeNumber>
                    <Class>ServoModule</Class><Version>1.0</Version>
                  </Module>
                </Environment>""";
        Path file = Files.writeString(temp.resolve("hall.xml"), xml);
        assertEquals(1, DescriptionLoader.loadEnvironment(file).getEnvironment().sizeOfModuleArray());
    }

    @Test
    void aWorldMayNameSeveralServersOfItsSpace() throws Exception {
        String xml = Files.readString(CHAPTER5).replace("<SpaceURL>http://localhost:9876/space</SpaceURL>",
                "<SpaceURL>http://pc-a:9876/space,http://pc-b:9876/space, http://192.168.1.3:9876/space</SpaceURL>");
        assertEquals("http://pc-a:9876/space,http://pc-b:9876/space, http://192.168.1.3:9876/space",
                DescriptionLoader.loadWorldFromString(xml, "cluster.xml").getRobotWorld().getSpaceURL());
    }
}
