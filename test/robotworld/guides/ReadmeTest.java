package robotworld.guides;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;

/**
 * The README's commands, run in order in a fresh clone of this repository (its committed files only: a file the
 * README needs but nobody committed fails here), with free ports in place of the README's fixed ones. The two
 * {@code ./antw} commands at its top are what runs this very test and the demo (DemoTest), so they are not run
 * again. The clone gets this build's {@code build/dist} instead of building itself, which the suite has just
 * done; {@code -Drwe.test.readme.fresh-build=true} lets {@code ./rwe} build the clone from scratch as on a new
 * machine (minutes, not seconds).
 */
class ReadmeTest {

    @TempDir
    Path folder;

    @Test
    void theReadmeStepByStepRunsInAFreshClone() throws Exception {
        Walkthrough.ant();
        Path root = ProjectFiles.root();
        assumeTrue(Files.isDirectory(root.resolve(".git")) || Files.isRegularFile(root.resolve(".git")),
                "not a git checkout: the README walkthrough clones the repository");
        Path clone = folder.resolve("clone");
        Process git = new ProcessBuilder("git", "clone", "-q", "--no-hardlinks", root.toString(), clone.toString())
                .redirectErrorStream(true).redirectOutput(folder.resolve("clone.log").toFile()).start();
        assertTrue(git.waitFor(120, TimeUnit.SECONDS) && git.exitValue() == 0, Walkthrough.tail(folder.resolve("clone.log")));
        if (!Boolean.getBoolean("rwe.test.readme.fresh-build")) {
            useThisBuild(clone);
        }

        List<Walkthrough.Block> blocks = Walkthrough.blocks(Files.readString(root.resolve("README.md")));
        String last = "";
        try (Walkthrough walk = new Walkthrough(clone, root, 9876, 5020, 5030)) {
            walk.freshClone();
            for (Walkthrough.Block block : blocks) {
                if (!block.language().equals("sh")) {
                    continue;
                }
                for (String command : block.commands()) {
                    if (command.startsWith("./antw ") || command.startsWith("kill ")) {
                        continue;
                    }
                    last = walk.run(command, Duration.ofMinutes(8));
                }
            }
            assertTrue(last.contains("bump-and-turn: ") && last.contains("stopped"), "the robot's program ran to its"
                    + " end:\n" + last);
            walk.assertBackgroundAlive();
            String monitor = walk.backgroundOutput("monitor");
            assertTrue(monitor.contains("Motor-Controller"), "the monitor saw the robot's program:\n" + monitor);
        }
        assertTrue(Files.isRegularFile(clone.resolve("my-world/MyWorld.xml")));
    }

    /** This build's dist, newer than the clone's sources, so ./rwe takes it as built. */
    private static void useThisBuild(Path clone) throws Exception {
        Path dist = Path.of(System.getProperty("rwe.build.dir", ProjectFiles.resolve("build").toString()))
                .resolve("dist");
        Path target = clone.resolve("build/dist");
        try (Stream<Path> files = Files.walk(dist)) {
            for (Path file : files.toList()) {
                Path copy = target.resolve(dist.relativize(file).toString());
                if (Files.isDirectory(file)) {
                    Files.createDirectories(copy);
                } else {
                    Files.copy(file, copy, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        Files.setLastModifiedTime(target.resolve("robotworldexplorer.jar"), FileTime.from(Instant.now().plusSeconds(60)));
    }
}
