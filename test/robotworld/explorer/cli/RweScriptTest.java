package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;

/** The {@code rwe} script, linked into a folder of its own as a user puts it into ~/bin, finds its checkout. */
class RweScriptTest {

    @TempDir
    Path temp;

    @Test
    void worksThroughASymbolicLinkFromAnotherFolder() throws Exception {
        Path bin = Files.createDirectories(temp.resolve("home/bin"));
        Path link = Files.createSymbolicLink(bin.resolve("rwe"), ProjectFiles.resolve("rwe"));
        Path twice = Files.createSymbolicLink(temp.resolve("rwe-again"), link); // a link to the link
        for (Path script : new Path[] {link, twice}) {
            Path log = temp.resolve("out.log");
            ProcessBuilder builder = new ProcessBuilder(script.toString(), "validate",
                    ProjectFiles.resolve("docs/examples/chapter5-world.xml").toString())
                    .directory(temp.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
            builder.environment().put("RWE_NO_BUILD", "1"); // ./antw test has built it, maybe elsewhere:
            if (System.getProperty("rwe.build.dir") != null) {
                builder.environment().put("RWE_BUILD_DIR", System.getProperty("rwe.build.dir"));
            }
            Process rwe = builder.start();
            assertTrue(rwe.waitFor(120, TimeUnit.SECONDS), "rwe did not end");
            String output = Files.readString(log);
            assertEquals(0, rwe.exitValue(), output);
            assertTrue(output.contains("valid RobotWorld 'Chapter5World'"), output);
        }
    }
}
