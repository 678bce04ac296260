package robotworld.program;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robotworld.testsupport.ProjectFiles;

/** The JVM options of a world's processes: valid on this JDK, in effect, and passed on by every launcher. */
class JvmOptionsTest {

    @Test
    void thisJdkStartsWithThemAndAppliesThem() throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString()));
        command.addAll(JvmOptions.LATENCY);
        command.addAll(List.of("-XX:+PrintFlagsFinal", "-version"));
        Process java = new ProcessBuilder(command).redirectErrorStream(true).start();
        String output = new String(java.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(java.waitFor(60, TimeUnit.SECONDS), "java -version did not end");
        assertEquals(0, java.exitValue(), output);
        assertTrue(output.matches("(?s).*\\bG1ConcRefinementThreads\\s*=\\s*0\\b.*"), output);
    }

    @Test
    void theRweScriptTheBuildAndGeneratedProjectsPassThemOn() throws Exception {
        for (String file : List.of("rwe", "build.xml", "resources/transfer/xvsm/build.xslt")) {
            String text = Files.readString(ProjectFiles.resolve(file));
            for (String option : JvmOptions.LATENCY) {
                assertTrue(text.contains(option), file + " does not pass " + option);
            }
        }
    }
}
