package robotworld.description;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;

/** Run-time schemas: how a new module type gets its {@code <Class>} value without rebuilding anything. */
public class DescriptionSchemasTest {

    @TempDir
    Path temp;

    /** A copy of schemas/ whose bus module classes also allow {@code newClass}. */
    public static Path schemasWithBusModuleClass(Path directory, String newClass) throws IOException {
        Files.createDirectories(directory);
        try (Stream<Path> files = Files.list(ProjectFiles.resolve("schemas"))) {
            for (Path file : files.toList()) {
                Files.copy(file, directory.resolve(file.getFileName()));
            }
        }
        Path types = directory.resolve("Types.xsd");
        String original = Files.readString(types);
        String marker = "<xsd:enumeration value=\"MotorModule\"/>";
        Files.writeString(types, original.replace(marker,
                marker + "\n      <xsd:enumeration value=\"" + newClass + "\"/>"));
        return directory;
    }

    private Path worldWith(String moduleClass) throws IOException {
        return Files.writeString(temp.resolve("world.xml"),
                Files.readString(ProjectFiles.resolve("docs/examples/chapter5-world.xml"))
                        .replace("<Class>BumperModule</Class>", "<Class>" + moduleClass + "</Class>"));
    }

    @Test
    void addedModuleClassIsValidOnlyWithTheExtendedSchemas() throws Exception {
        Path world = worldWith("GripperModule");
        DescriptionException builtIn = assertThrows(DescriptionException.class, () -> DescriptionLoader.loadWorld(
                world, DescriptionSchemas.builtIn()));
        assertTrue(builtIn.getMessage().contains("Class: a bus module's class is ServoModule, BumperModule,"
                + " IRDistanceModule or MotorModule; got 'GripperModule'"), builtIn.getMessage());

        DescriptionSchemas extended = DescriptionSchemas.fromDirectory(
                schemasWithBusModuleClass(temp.resolve("schemas"), "GripperModule"));
        RobotWorldType loaded = DescriptionLoader.loadWorld(world, extended).getRobotWorld();
        assertEquals("GripperModule", ModuleClassName.of(loaded.getRobotDescriptionArray(0).getModuleArray(1)));
    }

    @Test
    void extendedSchemasStillReportPositionsAndRules() throws Exception {
        DescriptionSchemas extended = DescriptionSchemas.fromDirectory(
                schemasWithBusModuleClass(temp.resolve("schemas"), "GripperModule"));
        Path badHouse = ProjectFiles.resolve("test/robotworld/description/invalid/bad-house-code.xml");
        DescriptionException schemaError = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(badHouse, extended));
        assertTrue(schemaError.getMessage().startsWith(badHouse + ":13:17: HouseCode: an X10 house code is one"
                + " capital letter from A to P; got 'Q'"), schemaError.getMessage());
        Path world = worldWith("Wheel");
        DescriptionException unknownClass = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(world, extended));
        assertTrue(unknownClass.getMessage().contains("MotorModule or GripperModule; got 'Wheel'"),
                unknownClass.getMessage()); // the choices of the schemas in use
        Path duplicate = ProjectFiles.resolve("test/robotworld/description/invalid/duplicate-participant.xml");
        DescriptionException ruleError = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(duplicate, extended));
        assertTrue(ruleError.getMessage().contains("duplicate participant name 'DimRoom'"), ruleError.getMessage());
    }

    @Test
    void brokenSchemaDirectoryIsReportedNotThrown() throws Exception {
        Path empty = Files.createDirectories(temp.resolve("empty"));
        DescriptionException missing = assertThrows(DescriptionException.class,
                () -> DescriptionSchemas.fromDirectory(empty));
        assertTrue(missing.getMessage().contains("RobotWorld.xsd: no such schema file"), missing.getMessage());

        Path broken = schemasWithBusModuleClass(temp.resolve("broken"), "GripperModule");
        Files.writeString(broken.resolve("Types.xsd"), Files.readString(broken.resolve("Types.xsd"))
                .replace("base=\"xsd:string\"", "base=\"xsd:nonsense\""));
        DescriptionException compile = assertThrows(DescriptionException.class,
                () -> DescriptionSchemas.fromDirectory(broken));
        assertTrue(compile.getMessage().contains("schema error"), compile.getMessage());
    }
}
