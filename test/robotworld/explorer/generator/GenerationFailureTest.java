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
        assertTrue(thrown.getMessage().contains("'my.class' is not a valid Java package name: it contains the Java"
                + " keyword 'class'"), thrown.getMessage());
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
    void aFailedGenerationRemovesTheParentDirectoriesItCreated() throws Exception {
        Path deep = temp.resolve("new/deeper/still/out");
        // fails after the destination's parents exist: while writing into the staging directory
        FrameworkGenerator failing = new FrameworkGenerator(FrameworkLibraries.defaultDirectory(),
                new ClassLoaderWithBrokenSource(GenerationFailureTest.class.getClassLoader()));
        assertThrows(GenerationException.class, () -> failing.generate(
                LISTING_3_5, "MyRobot", null, deep, false, GenerationListener.SILENT));
        assertEquals(List.of(), leftovers(), "no new/ left behind");
        Files.createDirectories(temp.resolve("kept"));
        assertThrows(GenerationException.class, () -> new FrameworkGenerator(temp.resolve("nojars")).generate(
                LISTING_3_5, "MyRobot", null, temp.resolve("kept/a/b"), false, GenerationListener.SILENT));
        assertEquals(List.of("kept"), leftovers(), "a directory that was there before stays");
    }

    /** Serves a source stylesheet that compiles but fails while transforming. */
    private static final class ClassLoaderWithBrokenSource extends ClassLoader {
        ClassLoaderWithBrokenSource(ClassLoader parent) {
            super(parent);
        }

        @Override
        public URL getResource(String name) {
            if (name.equals("transfer/none/source.xslt")) {
                try {
                    Path broken = Files.createTempFile("broken", ".xslt");
                    broken.toFile().deleteOnExit();
                    Files.writeString(broken, "<xsl:stylesheet version='3.0' xmlns:xsl='http://www.w3.org/1999/XSL/"
                            + "Transform'><xsl:template match='/'><xsl:sequence select=\"error((), 'boom')\"/>"
                            + "</xsl:template></xsl:stylesheet>");
                    return broken.toUri().toURL();
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }
            return super.getResource(name);
        }
    }

    /** A project's directories and files get the modes the user's umask allows, not a private 0700. */
    @Test
    void theProjectHonoursTheUmask() throws Exception {
        Path out = temp.resolve("out");
        generator.generate(LISTING_3_5, "MyRobot", null, out, false, GenerationListener.SILENT);
        Path probe = Files.createDirectory(temp.resolve("probe")); // made with the umask of this process
        assertEquals(Files.getPosixFilePermissions(probe), Files.getPosixFilePermissions(out));
        assertEquals(Files.getPosixFilePermissions(probe), Files.getPosixFilePermissions(out.resolve("src")));
        Path probeFile = Files.writeString(temp.resolve("probe.txt"), "x");
        assertEquals(Files.getPosixFilePermissions(probeFile), Files.getPosixFilePermissions(out.resolve("build.xml")));
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
