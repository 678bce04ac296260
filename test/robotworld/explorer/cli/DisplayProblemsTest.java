package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;
import robotworld.testsupport.TestPeers;

/**
 * Display problems as a user meets them, with the real command in a JVM of its own: no display, a DISPLAY that
 * names no X server, a headless Java. Each ends with one line saying so and what to do, never a stack trace; the
 * demo falls back to the console monitor and still prints its summary.
 */
class DisplayProblemsTest {

    private static final String WORLD = "docs/examples/chapter5-world.xml";

    @TempDir
    Path temp;

    private record Run(int exit, String out, String err) {
    }

    private Run rwe(Map<String, String> environment, List<String> jvmOptions, String... args) throws Exception {
        Path jar = Path.of(System.getProperty("rwe.build.dir", "build"), "dist", "robotworldexplorer.jar");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString()));
        command.addAll(jvmOptions);
        command.add("-Drwe.home=" + ProjectFiles.root());
        command.add("-Drwe.monitor.layout=none");
        command.add("-Drwe.framework.dir=" + System.getProperty("rwe.framework.dir", "build/dist/framework"));
        command.add("-Drwe.ant.home=" + System.getProperty("rwe.ant.home", "/usr/share/ant"));
        command.addAll(List.of("-jar", jar.toString()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).directory(ProjectFiles.root().toFile());
        builder.environment().remove("DISPLAY");
        builder.environment().putAll(environment);
        Path out = temp.resolve("out-" + System.nanoTime());
        Path err = temp.resolve("err-" + System.nanoTime());
        Process process = builder.redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!process.waitFor(240, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("rwe did not end: " + read(out) + read(err));
        }
        return new Run(process.exitValue(), read(out), read(err));
    }

    private static String read(Path file) throws IOException {
        return Files.exists(file) ? Files.readString(file, StandardCharsets.UTF_8) : "";
    }

    private static void assertOneClearLine(Run run, String expected) {
        assertEquals(1, run.exit(), run.err());
        assertEquals("", run.out());
        assertEquals(List.of(expected), run.err().lines().toList(), "exactly one line on stderr");
    }

    @Test
    void aDisplayThatNamesNoXServerIsOneLineSuggestingConsole() throws Exception {
        TestPeers.requireFullJre(); // a headless runtime says it is headless before it looks at the display
        assertOneClearLine(rwe(Map.of("DISPLAY", ":9999"), List.of(), "monitor", WORLD),
                "rwe monitor: cannot open the display ':9999' (no X server answers there); use --console for a text "
                        + "view");
    }

    @Test
    void noDisplayAtAllIsOneLineToo() throws Exception {
        assertOneClearLine(rwe(Map.of(), List.of(), "monitor", WORLD),
                "rwe monitor: no display (DISPLAY is not set); use --console for a text view");
    }

    @Test
    void aHeadlessJavaIsOneLineToo() throws Exception {
        assertOneClearLine(rwe(Map.of("DISPLAY", ":9999"), List.of("-Djava.awt.headless=true"), "monitor", WORLD),
                "rwe monitor: this Java runtime runs headless (java.awt.headless=true); use --console for a text view");
    }

    @Test
    void theDemoFallsBackToTheConsoleMonitorAndStillSummarizes() throws Exception {
        TestPeers.requireFullJre();
        Run run = rwe(Map.of("DISPLAY", ":9999"), List.of(), "demo", "--seconds", "12", "--out",
                temp.resolve("demo").toString());
        String all = run.out() + run.err();
        assertTrue(all.contains("no monitor window: cannot open the display ':9999' (no X server answers there); "
                + "the console monitor shows the run instead"), all);
        assertTrue(all.contains("monitor | "), "the console monitor's lines\n" + all);
        assertTrue(all.contains("result "), "the summary\n" + all);
        assertFalse(all.contains("\tat ") || all.contains("Exception in thread") || all.contains("AWTError"),
                "no stack trace\n" + all);
        assertEquals(0, run.exit(), all);
    }
}
