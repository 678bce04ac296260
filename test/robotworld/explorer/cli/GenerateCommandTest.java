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
import robotworld.testsupport.ProjectFiles;

class GenerateCommandTest {

    @TempDir
    Path temp;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int rwe(String... args) {
        return Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void generatesAndSaysHowToBuild() {
        Path project = temp.resolve("MyRobot");
        int code = rwe("generate", ProjectFiles.resolve("docs/examples/listing-3-5-world.xml").toString(),
                "--viewpoint", "MyRobot", "--out", project.toString());
        assertEquals(0, code, err.toString());
        assertTrue(out.toString().contains("main class mypackage.MyRobot"), out.toString());
        assertTrue(out.toString().contains("\n  cd " + project + " && ant run -Drwe.port.MyRobot.bus=/dev/ttyUSB0\n"),
                "the exact command, ports included: " + out);
        assertTrue(err.toString().contains("] writing MyRobot.java"), "progress is shown: " + err);
        assertTrue(Files.isRegularFile(project.resolve("src/mypackage/MyRobot.java")));
    }

    @Test
    void errorsAreOneLineEachAndNothingIsWritten() {
        int code = rwe("generate", ProjectFiles.resolve("docs/examples/listing-3-5-world.xml").toString(),
                "--viewpoint", "Ghost", "--out", temp.resolve("x").toString());
        assertEquals(1, code);
        assertTrue(err.toString().contains("rwe generate: unknown viewpoint 'Ghost'"), err.toString());
        assertFalse(err.toString().contains("\tat "), err.toString());
        assertFalse(Files.exists(temp.resolve("x")));

        String bad = ProjectFiles.resolve("test/robotworld/description/invalid/bad-house-code.xml").toString();
        assertEquals(1, rwe("generate", bad, "--viewpoint", "DimRoom", "--out", temp.resolve("y").toString()));
        assertTrue(err.toString().contains(bad + ":13:17:"), err.toString());
    }

    @Test
    void viewpointAndOutAreRequired() {
        assertEquals(2, rwe("generate", "world.xml"));
        assertTrue(err.toString().contains("--viewpoint") || err.toString().contains("--out"), err.toString());
        assertTrue(err.toString().endsWith("see 'rwe generate --help'\n"), err.toString());
        assertEquals(2, err.toString().lines().count(), "the message and where the help is, no usage dump: " + err);
    }
}
