package robotworld.description;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import robotworld.testsupport.ProjectFiles;

/** Every description the project ships is valid, and the module catalogue is complete and documented. */
class ExampleDescriptionsTest {

    static Stream<Path> shippedDescriptions() throws IOException {
        return Stream.concat(xmlFiles("docs/examples"), xmlFiles("ModuleDescriptions"));
    }

    private static Stream<Path> xmlFiles(String directory) throws IOException {
        try (Stream<Path> files = Files.walk(ProjectFiles.resolve(directory))) {
            return files.filter(f -> f.toString().endsWith(".xml")).sorted().collect(Collectors.toList()).stream();
        }
    }

    @ParameterizedTest
    @MethodSource("shippedDescriptions")
    void shippedDescriptionIsValid(Path file) throws Exception {
        DescriptionLoader.load(file, null);
    }

    @Test
    void bothThesisWorldsAreShipped() throws Exception {
        RobotWorldType chapter5 = DescriptionLoader.loadWorld(ProjectFiles.resolve("docs/examples/chapter5-world.xml"))
                .getRobotWorld();
        assertEquals(1, chapter5.sizeOfEnvironmentArray());
        assertEquals(List.of("MotorModule", "BumperModule"),
                Stream.of(chapter5.getRobotDescriptionArray(0).getModuleArray())
                        .map(m -> m.getClass1().toString()).toList());
        assertEquals("X10ApplianceModule", chapter5.getEnvironmentArray(0).getX10ModuleArray(0).getClass1().toString());

        RobotWorldType lab = DescriptionLoader.loadWorld(ProjectFiles.resolve("docs/examples/lab-world.xml"))
                .getRobotWorld();
        assertEquals("OEFAI_Labor", lab.getEnvironmentArray(0).getEnvironmentName());
        assertEquals(List.of("MyRobot1", "MyRobot2"),
                Stream.of(lab.getRobotDescriptionArray()).map(ModuleListType::getRobotName).toList());
    }

    @Test
    void moduleCatalogueHasOneDescriptionPerModuleClassKeyedByNodeId() throws Exception {
        Set<String> classes = new TreeSet<>();
        for (Path file : xmlFiles("ModuleDescriptions").toList()) {
            ModuleDescriptionType module = DescriptionLoader.loadModuleDescription(file).getModuleDescription();
            assertEquals(module.getNodeID() + ".xml", file.getFileName().toString(), "file name must be the NodeID");
            assertTrue(classes.add(module.getClass1().toString()), "two descriptions for " + module.getClass1());
            Path page = ProjectFiles.resolve(module.getDocRef());
            assertTrue(Files.isRegularFile(page), module.getNodeID() + ": DocRef " + module.getDocRef() + " is missing");
            assertTrue(Files.readString(page).startsWith("# "), page + " should be a documentation page");
        }
        Set<String> expected = new TreeSet<>();
        EnumSet.allOf(Modules.class).forEach(m -> expected.add(m.name()));
        assertEquals(expected, classes);
    }

    /** The module classes of the prototype (thesis appendix B). */
    private enum Modules { MotorModule, ServoModule, BumperModule, IRDistanceModule, X10LampModule, X10ApplianceModule }
}
