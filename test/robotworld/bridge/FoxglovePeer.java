package robotworld.bridge;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import robotworld.testsupport.ProjectFiles;
import robotworld.testsupport.TestPeers;

/**
 * The reference Foxglove WebSocket client (npm {@code @foxglove/ws-protocol}'s FoxgloveClient) run by
 * {@code foxglove_peer.js}: its events as JSON nodes, as they arrive. Skips the test when node or the package is
 * missing.
 */
final class FoxglovePeer implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();
    private final Process process;
    private final List<JsonNode> events = new CopyOnWriteArrayList<>();
    private final StringBuilder errors = new StringBuilder();
    private final Thread reader;

    private FoxglovePeer(Process process) {
        this.process = process;
        reader = new Thread(() -> {
            try (BufferedReader lines = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String line = lines.readLine(); line != null; line = lines.readLine()) {
                    events.add(JSON.readTree(line));
                }
            } catch (IOException e) {
                // the process ended
            }
        }, "foxglove-peer-out");
        reader.setDaemon(true);
        reader.start();
        Thread errorReader = new Thread(() -> {
            try {
                String text = new String(process.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
                synchronized (errors) {
                    errors.append(text);
                }
            } catch (IOException e) {
                // the process ended
            }
        }, "foxglove-peer-err");
        errorReader.setDaemon(true);
        errorReader.start();
    }

    /** Connects to {@code uri} and subscribes to {@code topics} (all when none). */
    static FoxglovePeer connect(URI uri, String... topics) throws IOException {
        Path modules = TestPeers.nodeModules("@foxglove/ws-protocol");
        TestPeers.nodeModules("ws");
        List<String> command = new ArrayList<>(List.of("node",
                ProjectFiles.resolve("test/robotworld/bridge/foxglove_peer.js").toString(), uri.toString(), "300"));
        command.addAll(List.of(topics));
        ProcessBuilder builder = new ProcessBuilder(command);
        builder.environment().put("NODE_PATH", modules.toString());
        return new FoxglovePeer(builder.start());
    }

    /** Every event so far. */
    List<JsonNode> events() {
        return List.copyOf(events);
    }

    /** The events named {@code event} so far. */
    List<JsonNode> events(String event) {
        return events.stream().filter(e -> e.path("event").asText().equals(event)).toList();
    }

    /** Waits (up to a minute) until some event matches. */
    JsonNode await(Predicate<JsonNode> match, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            for (JsonNode event : events) {
                if (match.test(event)) {
                    return event;
                }
            }
            if (!process.isAlive() && process.exitValue() != 0) {
                throw new AssertionError("the Foxglove client ended with " + process.exitValue() + " before " + what
                        + ": " + events + " " + errors());
            }
            Thread.sleep(20);
        }
        throw new AssertionError("the Foxglove client did not see " + what + " within 60 s: " + events + " "
                + errors());
    }

    /** Waits (up to a minute) until the client ends, e.g. after a refused connection; its exit code. */
    int awaitEnd() throws InterruptedException {
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            throw new AssertionError("the Foxglove client still runs after 60 s: " + events + " " + errors());
        }
        reader.join(10_000); // every event it printed is read
        return process.exitValue();
    }

    String errors() {
        synchronized (errors) {
            return errors.toString();
        }
    }

    @Override
    public void close() {
        try {
            process.getOutputStream().close(); // the peer ends when its input closes
        } catch (IOException e) {
            // gone already
        }
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }
}
