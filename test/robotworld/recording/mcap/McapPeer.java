package robotworld.recording.mcap;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import robotworld.testsupport.ProjectFiles;
import robotworld.testsupport.TestPeers;

/**
 * The reference Python {@code mcap} package (test-setup/requirements.txt) driven through {@code mcap_peer.py}:
 * reads a file and reports what it found as JSON, or writes one from a JSON description. Skips the test when the
 * package is missing.
 */
public final class McapPeer {

    private static final ObjectMapper JSON = new ObjectMapper();
    private final String python;

    private McapPeer(String python) {
        this.python = python;
    }

    /** The peer, or the test is skipped (naming how to install it). */
    public static McapPeer require() {
        return new McapPeer(TestPeers.python("mcap"));
    }

    /** What the reference reader finds in {@code file} (see mcap_peer.py for the fields). */
    public JsonNode read(Path file) throws IOException, InterruptedException {
        return JSON.readTree(run("read", file.toString()));
    }

    /** Writes {@code file} with the reference writer from {@code spec} (see mcap_peer.py). */
    public void write(Path file, JsonNode spec, Path temp) throws IOException, InterruptedException {
        Path specFile = temp.resolve("spec-" + System.nanoTime() + ".json");
        JSON.writeValue(specFile.toFile(), spec);
        run("write", file.toString(), specFile.toString());
    }

    private String run(String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(python,
                ProjectFiles.resolve("test/robotworld/recording/mcap/mcap_peer.py").toString()));
        command.addAll(List.of(args));
        Process process = new ProcessBuilder(command).redirectErrorStream(false).start();
        byte[] out = process.getInputStream().readAllBytes();
        byte[] err = process.getErrorStream().readAllBytes();
        if (!process.waitFor(120, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new IOException("the Python mcap peer did not finish: " + command);
        }
        assertEquals(0, process.exitValue(), "the Python mcap peer failed: " + new String(err, StandardCharsets.UTF_8));
        return new String(out, StandardCharsets.UTF_8);
    }
}
