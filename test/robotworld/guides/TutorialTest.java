package robotworld.guides;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.ProjectFiles;

/**
 * docs/tutorial.md, followed literally: its shell commands run in order against the simulators (with free ports
 * in place of its fixed ones), its control program goes where it says, and both runs (on the robot's computer and
 * moved to the external viewpoint) end by themselves with their summary line.
 */
class TutorialTest {

    private static final Pattern DONE = Pattern.compile("done: (\\d+) turns, closest obstacle (\\d+) mm");

    @TempDir
    Path folder;

    @Test
    void theTutorialRunsAsWritten() throws Exception {
        Walkthrough.ant();
        List<Walkthrough.Block> blocks = Walkthrough.blocks(Files.readString(ProjectFiles.resolve("docs/tutorial.md")));
        List<String> summaries = new ArrayList<>();
        String program = null;
        try (Walkthrough walk = new Walkthrough(folder, ProjectFiles.root(), 9876, 5020, 5030)) {
            walk.linkCheckout("rwe", "docs");
            for (Walkthrough.Block block : blocks) {
                switch (block.language()) {
                    case "sh" -> {
                        for (String command : block.commands()) {
                            if (command.startsWith("kill ")) {
                                continue; // the guide's clean-up of its own shell's jobs; ours are closed below
                            }
                            String output = walk.run(command, Duration.ofMinutes(5));
                            Matcher done = DONE.matcher(output);
                            if (done.find()) {
                                summaries.add(done.group());
                                walk.assertBackgroundAlive();
                            }
                        }
                    }
                    case "java" -> {
                        program = block.text();
                        walk.writeControlProgram(block.info().replace("control=", ""), program);
                    }
                    case "same" -> {
                        assertNotNull(program, "the guide reuses a program it has not shown yet");
                        walk.writeControlProgram(block.info().replace("control=", ""), program);
                    }
                    default -> {
                        // text: sample output, not a command
                    }
                }
            }
        }
        System.out.println("tutorial runs: " + summaries);
        assertEquals(2, summaries.size(), "both runs of the control program end with their summary: " + summaries);
        for (String summary : summaries) {
            Matcher done = DONE.matcher(summary);
            assertTrue(done.find() && Integer.parseInt(done.group(2)) < 800, "the robot saw something: " + summary);
        }
    }
}
