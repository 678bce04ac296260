package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.description.DescriptionException;
import robotworld.explorer.FrameworkGenerator;
import robotworld.testsupport.ProjectFiles;

/** Every way generation can fail says what went wrong and leaves nothing behind. */
class GenerationFailureTest {

    private static final Path LISTING_3_5 = ProjectFiles.resolve("docs/examples/listing-3-5-world.xml");

    @TempDir
    Path temp;

    private final FrameworkGenerator generator = new FrameworkGenerator();

    private List<String> leftovers() throws IOException {
        try (Stream<Path> files = Files.list(temp)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void invalidWorldIsReportedWithPositions() throws Exception {
        Path bad = ProjectFiles.resolve("test/robotworld/description/invalid/unit-code-seventeen.xml");
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> generator.generate(bad, "DimRoom", null, temp.resolve("out"), false, GenerationListener.SILENT));
        assertTrue(thrown.getMessage().contains(":14:16:"), thrown.getMessage());
        assertEquals(List.of(), leftovers());
    }

    @Test
    void unknownViewpointListsTheChoices() throws Exception {
        GenerationException thrown = assertThrows(GenerationException.class, () -> generator.generate(
                LISTING_3_5, "Nobody", null, temp.resolve("out"), false, GenerationListener.SILENT));
        assertTrue(thrown.getMessage().contains("unknown viewpoint 'Nobody'")
                && thrown.getMessage().contains("[MyRobot]"), thrown.getMessage());
        assertEquals(List.of(), leftovers());
    }

    @Test
    void externalViewpointNeedsASpace() throws Exception {
        GenerationException thrown = assertThrows(GenerationException.class, () -> generator.generate(
                LISTING_3_5, "external", null, temp.resolve("out"), false, GenerationListener.SILENT));
        assertTrue(thrown.getMessage().contains("no external viewpoint"), thrown.getMessage());
    }

    @Test
    void invalidPackageIsRefused() throws Exception {
        GenerationException thrown = assertThrows(GenerationException.class, () -> generator.generate(
                LISTING_3_5, "MyRobot", "my.class", temp.resolve("out"), false, GenerationListener.SILENT));
        assertTrue(thrown.getMessage().contains("'my.class' is not a valid Java package name"), thrown.getMessage());
        assertEquals(List.of(), leftovers());
    }

    @Test
    void unwritableDestinationIsNamed() throws Exception {
        Path file = Files.writeString(temp.resolve("a-file"), "not a directory");
        GenerationException thrown = assertThrows(GenerationException.class, () -> generator.generate(
                LISTING_3_5, "MyRobot", null, file.resolve("out"), false, GenerationListener.SILENT));
        assertTrue(thrown.getMessage().startsWith("cannot write to " + file), thrown.getMessage());
        assertEquals(List.of("a-file"), leftovers());
    }

    @Test
    void missingStylesheetFailsBeforeAnythingIsWritten() throws Exception {
        try (URLClassLoader empty = new URLClassLoader(new URL[0], null)) {
            FrameworkGenerator bare = new FrameworkGenerator(FrameworkLibraries.defaultDirectory(), empty);
            GenerationException thrown = assertThrows(GenerationException.class, () -> bare.generate(
                    LISTING_3_5, "MyRobot", null, temp.resolve("out"), false, GenerationListener.SILENT));
            assertTrue(thrown.getMessage().contains("no stylesheet transfer/none/build.xslt"), thrown.getMessage());
        }
        assertEquals(List.of(), leftovers());
    }

    @Test
    void nonEmptyDestinationIsRefusedUnlessForced() throws Exception {
        Path out = Files.createDirectories(temp.resolve("out"));
        Files.writeString(out.resolve("notes.txt"), "my notes");
        GenerationException thrown = assertThrows(GenerationException.class, () -> generator.generate(
                LISTING_3_5, "MyRobot", null, out, false, GenerationListener.SILENT));
        assertTrue(thrown.getMessage().contains("exists and is not empty") && thrown.getMessage().contains("--force"),
                thrown.getMessage());
        assertEquals("my notes", Files.readString(out.resolve("notes.txt")), "the old content is untouched");
        assertEquals(List.of("out"), leftovers());

        generator.generate(LISTING_3_5, "MyRobot", null, out, true, GenerationListener.SILENT);
        assertFalse(Files.exists(out.resolve("notes.txt")), "forced generation replaces the directory");
        assertTrue(Files.exists(out.resolve("build.xml")));
        assertEquals(List.of("out"), leftovers(), "no staging directory is left");
    }

    @Test
    void failureInsideTheStylesheetLeavesNothing() throws Exception {
        // a framework directory without the runtime jar is found out before writing
        Path noJars = Files.createDirectories(temp.resolve("nojars"));
        FrameworkGenerator broken = new FrameworkGenerator(noJars);
        GenerationException thrown = assertThrows(GenerationException.class, () -> broken.generate(
                LISTING_3_5, "MyRobot", null, temp.resolve("out"), false, GenerationListener.SILENT));
        assertTrue(thrown.getMessage().contains("robotworld-runtime.jar"), thrown.getMessage());
        assertEquals(List.of("nojars"), leftovers());
    }
}
