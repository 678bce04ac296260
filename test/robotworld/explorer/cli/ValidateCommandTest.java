package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import robotworld.testsupport.ProjectFiles;

class ValidateCommandTest {

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int rwe(String... args) {
        return Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    private static String file(String relative) {
        return ProjectFiles.resolve(relative).toString();
    }

    @Test
    void validFilesExitZeroWithASummaryPerFile() {
        int code = rwe("validate", file("docs/examples/chapter5-world.xml"), file("docs/examples/parts/dim-room.xml"));
        assertEquals(0, code, err.toString());
        assertTrue(out.toString().contains("chapter5-world.xml: valid RobotWorld 'Chapter5World' (xvsm): "
                + "1 environment, 1 robot, 3 modules"), out.toString());
        assertTrue(out.toString().contains("2 valid, 0 invalid"), out.toString());
    }

    @Test
    void invalidFileExitsOneWithPositionedErrorsAndNoStackTrace() {
        String bad = file("test/robotworld/description/invalid/unit-code-seventeen.xml");
        int code = rwe("validate", file("docs/examples/lab-world.xml"), bad);
        assertEquals(1, code);
        assertTrue(err.toString().startsWith(bad + ":14:16: UnitCode: an X10 unit code is a number word from ONE to"
                + " SIXTEEN; got 'SEVENTEEN'"), err.toString());
        assertTrue(out.toString().contains("1 valid, 1 invalid"), out.toString());
        assertFalse(err.toString().contains("Exception"), err.toString());
        assertFalse(err.toString().contains("\tat "), err.toString());
    }

    @Test
    void everyCorpusFileIsReportedWithoutAStackTrace() throws Exception {
        try (var files = java.nio.file.Files.list(ProjectFiles.resolve("test/robotworld/description/invalid"))) {
            String[] args = java.util.stream.Stream.concat(java.util.stream.Stream.of("validate"),
                    files.filter(f -> f.toString().endsWith(".xml")).map(Object::toString)).toArray(String[]::new);
            assertEquals(1, rwe(args));
        }
        assertFalse(err.toString().contains("\tat "), err.toString());
        assertFalse(err.toString().contains("Exception"), err.toString());
        assertTrue(out.toString().contains("0 valid, "), out.toString());
    }

    @Test
    void missingArgumentIsAUsageError() {
        assertEquals(2, rwe("validate"));
        assertEquals("rwe validate: missing 'FILE'\nsee 'rwe validate --help'\n", err.toString().replace("\r", ""));
    }

    @Test
    void anUnknownVerbIsNamedWithTheVerbsThereAre() {
        assertEquals(2, rwe("bogus"));
        String[] lines = err.toString().replace("\r", "").split("\n");
        assertEquals(2, lines.length, err.toString());
        assertTrue(lines[0].startsWith("rwe: unknown verb 'bogus'; the verbs are "), lines[0]);
        assertTrue(lines[0].contains("validate") && lines[0].contains("explore"), lines[0]);
        assertEquals("see 'rwe --help'", lines[1]);
    }

    @Test
    void helpListsTheVerbs() {
        assertEquals(0, rwe("--help"));
        assertTrue(out.toString().contains("validate"), out.toString());
    }
}
