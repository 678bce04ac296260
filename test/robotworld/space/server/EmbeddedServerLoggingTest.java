package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * A program that embeds a space server on the framework's runtime jars (as a generated project has them) prints
 * nothing of Jetty's start and stop; a system property brings Jetty's messages back.
 */
class EmbeddedServerLoggingTest {

    @Test
    void anEmbeddedServerStartsAndStopsQuietly() throws Exception {
        List<String> lines = runEmbeddingProgram();
        assertEquals(1, lines.size(), "only the program's own line: " + lines);
        assertTrue(lines.get(0).matches("serving http://127\\.0\\.0\\.1:\\d+/space"), lines.get(0));
    }

    @Test
    void jettysMessagesCanBeTurnedBackOn() throws Exception {
        List<String> lines = runEmbeddingProgram("-Dorg.eclipse.jetty.LEVEL=INFO");
        assertTrue(lines.stream().anyMatch(line -> line.contains(":INFO :") && line.contains("Started")),
                String.join("\n", lines));
    }

    private static List<String> runEmbeddingProgram(String... jvmOptions) throws Exception {
        Path framework = Path.of(System.getProperty("rwe.framework.dir", "build/dist/framework"));
        Path testClasses = Path.of(EmbeddedServerMain.class.getProtectionDomain().getCodeSource().getLocation()
                .toURI());
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString()));
        command.addAll(List.of(jvmOptions));
        command.addAll(List.of("-cp", framework.resolve("*") + File.pathSeparator + testClasses,
                EmbeddedServerMain.class.getName()));
        Process program = new ProcessBuilder(command).redirectErrorStream(true).start();
        if (!program.waitFor(60, TimeUnit.SECONDS)) {
            program.destroyForcibly();
            throw new IOException("the embedding program did not end within 60 s");
        }
        String output = new String(program.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, program.exitValue(), output);
        return output.lines().filter(line -> !line.isBlank()).toList();
    }
}
