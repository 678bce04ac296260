package robotworld.guides;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Runs the commands of a guide (a Markdown file) as a reader would type them, in a folder of its own: every line of
 * its {@code sh} code blocks through bash, a line ending in {@code &} as a background process (waited for until it
 * says {@code Ctrl-C}, as every server, simulator and serving program does), and a {@code java control=FILE} block
 * put between the control markers of that file. The fixed ports of the guide are replaced by free ones, so that
 * runs beside each other do not meet; {@code ./rwe} and {@code docs/} are links to this checkout; {@code ant} is
 * the one the build runs on.
 */
final class Walkthrough implements AutoCloseable {

    static final String CONTROL_BEGIN = "// >>> control logic begins here";
    static final String CONTROL_END = "// <<< control logic ends here";

    /** One code block of a guide, in order. */
    record Block(String language, String info, String text) {
        List<String> commands() {
            List<String> commands = new ArrayList<>();
            StringBuilder pending = new StringBuilder();
            for (String line : text.lines().toList()) {
                String stripped = line.strip();
                if (pending.isEmpty() && (stripped.isEmpty() || stripped.startsWith("#"))) {
                    continue;
                }
                if (stripped.endsWith("\\")) {
                    pending.append(stripped, 0, stripped.length() - 1).append(' ');
                    continue;
                }
                commands.add(pending + stripped);
                pending.setLength(0);
            }
            return commands;
        }
    }

    private static final Pattern FENCE = Pattern.compile("(?m)^```(\\w*)([^\\n]*)\\n(.*?)^```", Pattern.DOTALL);
    private static final Pattern HIDDEN = Pattern.compile("<!--[^>]*?control=(\\S+) -->");

    private final Path folder;
    private final Path root;
    private final Map<String, String> ports = new LinkedHashMap<>();
    private final List<Process> background = new ArrayList<>();
    private final List<Path> logs = new ArrayList<>();
    private final List<String> backgroundCommands = new ArrayList<>();
    private boolean freshClone;
    private int commandNumber;

    /** A walkthrough in {@code folder}, replacing each of {@code fixedPorts} by a free port. */
    Walkthrough(Path folder, Path root, int... fixedPorts) throws IOException {
        this.folder = folder;
        this.root = root;
        for (int port : fixedPorts) {
            ports.put(Integer.toString(port), Integer.toString(freePort()));
        }
    }

    /** Skips the test unless Ant is there (the build passes the Ant it runs on). */
    static String ant() {
        String antHome = System.getProperty("rwe.ant.home");
        Path ant = antHome == null ? null : Path.of(antHome, "bin", "ant");
        assumeTrue(ant != null && Files.isExecutable(ant), "no Ant for the generated projects: run the tests with"
                + " ./antw test, which passes its own");
        return ant.getParent().toString();
    }

    /** The code blocks of a guide, with the hidden "same program" markers as blocks of language {@code same}. */
    static List<Block> blocks(String markdown) {
        List<Block> blocks = new ArrayList<>();
        int at = 0;
        Matcher fence = FENCE.matcher(markdown);
        Matcher hidden = HIDDEN.matcher(markdown);
        while (true) {
            boolean nextFence = fence.find(at);
            int fenceStart = nextFence ? fence.start() : Integer.MAX_VALUE;
            boolean nextHidden = hidden.find(at);
            int hiddenStart = nextHidden ? hidden.start() : Integer.MAX_VALUE;
            if (!nextFence && !nextHidden) {
                return blocks;
            }
            if (hiddenStart < fenceStart) {
                blocks.add(new Block("same", "control=" + hidden.group(1), ""));
                at = hidden.end();
            } else {
                blocks.add(new Block(fence.group(1), fence.group(2).strip(), fence.group(3)));
                at = fence.end();
            }
        }
    }

    /** The link the guide's commands see as {@code ./rwe}, {@code docs/} and, if given, other files of the checkout. */
    void linkCheckout(String... names) throws IOException {
        for (String name : names) {
            Files.createSymbolicLink(folder.resolve(name), root.resolve(name));
        }
    }

    /** The folder is a clone of its own: ./rwe decides itself whether to build, as for a reader. */
    void freshClone() {
        freshClone = true;
    }

    /** The output so far of the first background command containing {@code part}. */
    String backgroundOutput(String part) throws IOException {
        for (int i = 0; i < backgroundCommands.size(); i++) {
            if (backgroundCommands.get(i).contains(part)) {
                return Files.readString(logs.get(i), StandardCharsets.UTF_8);
            }
        }
        throw new AssertionError("no background command with '" + part + "'");
    }

    /** {@code text} with the guide's fixed ports replaced. */
    String withPorts(String text) {
        String result = text;
        for (Map.Entry<String, String> port : ports.entrySet()) {
            result = result.replaceAll("(?<![0-9])" + port.getKey() + "(?![0-9])", port.getValue());
        }
        return result;
    }

    /** Runs one command line of the guide; returns its output (standard output and error together). */
    String run(String command, Duration limit) throws IOException, InterruptedException {
        String line = withPorts(command);
        if (line.endsWith("&")) {
            startInBackground(line.substring(0, line.length() - 1).strip());
            return "";
        }
        Path log = folder.resolve("command-" + (++commandNumber) + ".log");
        long started = System.nanoTime();
        Process process = start(line, log);
        if (!process.waitFor(limit.toMillis(), TimeUnit.MILLISECONDS)) {
            destroy(process);
            fail("'" + line + "' did not end within " + limit.toSeconds() + " s:\n" + tail(log));
        }
        String output = Files.readString(log, StandardCharsets.UTF_8);
        System.out.printf("%6.1f s  %s%n", (System.nanoTime() - started) / 1e9, line);
        assertEquals(0, process.exitValue(), "'" + line + "' failed:\n" + output);
        return output;
    }

    private void startInBackground(String line) throws IOException, InterruptedException {
        Path log = folder.resolve("background-" + (background.size() + 1) + ".log");
        long started = System.nanoTime();
        Process process = start(line, log);
        background.add(process);
        logs.add(log);
        backgroundCommands.add(line);
        long deadline = System.nanoTime() + Duration.ofSeconds(180).toNanos();
        while (!Files.readString(log, StandardCharsets.UTF_8).contains("Ctrl-C")) {
            if (!process.isAlive()) {
                fail("'" + line + "' ended at once:\n" + tail(log));
            }
            if (System.nanoTime() - deadline > 0) {
                fail("'" + line + "' did not get ready within 180 s:\n" + tail(log));
            }
            Thread.sleep(100);
        }
        System.out.printf("%6.1f s  %s &  (until ready)%n", (System.nanoTime() - started) / 1e9, line);
    }

    private Process start(String line, Path log) throws IOException {
        ProcessBuilder builder = new ProcessBuilder("bash", "-c", line).directory(folder.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile());
        Map<String, String> environment = builder.environment();
        environment.put("PATH", ant() + File.pathSeparator + Path.of(System.getProperty("java.home"), "bin")
                + File.pathSeparator + environment.getOrDefault("PATH", "/usr/bin:/bin"));
        environment.put("JAVA_HOME", System.getProperty("java.home"));
        relaxTimings(environment);
        if (!freshClone) {
            environment.put("RWE_NO_BUILD", "1"); // ./antw test built it; never a second build beside this one
            String buildDir = System.getProperty("rwe.build.dir");
            if (buildDir != null) {
                environment.put("RWE_BUILD_DIR", buildDir);
            }
        }
        return builder.start();
    }

    /**
     * The programs a guide starts get the safety deadlines and bus reply time the suite's own JVMs get (build.xml):
     * a guide's test is about its steps, and a program starved of CPU for half a second by the rest of the suite
     * must not be stopped by the safety layer (500 ms by default) or give up on the simulator (100 ms). The safety
     * tests set the timings they are about. Environment variables, so they reach every program a step starts.
     */
    static void relaxTimings(Map<String, String> environment) {
        environment.putIfAbsent("RWE_COMMAND_TIMEOUT_MS", "10000");
        environment.putIfAbsent("RWE_WATCHDOG_MS", "10000");
        environment.putIfAbsent("RWE_BUS_TIMEOUT_MS", "1000");
    }

    /** Puts {@code program} between the control markers of {@code relative}, in place of what is there. */
    void writeControlProgram(String relative, String program) throws IOException {
        Path file = folder.resolve(relative);
        assertTrue(Files.isRegularFile(file), "the guide names " + relative + ", which was not generated");
        String source = Files.readString(file);
        int begin = source.indexOf(CONTROL_BEGIN);
        int end = source.indexOf(CONTROL_END);
        assertTrue(begin > 0 && end > begin, relative + " has no control markers");
        int afterBegin = source.indexOf('\n', begin) + 1;
        int endLine = source.lastIndexOf('\n', end) + 1;
        String indented = program.lines().map(l -> l.isBlank() ? "" : "        " + l)
                .reduce("", (a, b) -> a + b + "\n");
        Files.writeString(file, source.substring(0, afterBegin) + indented + source.substring(endLine));
    }

    /** Whether every background process still runs; they should, until the walkthrough closes. */
    void assertBackgroundAlive() throws IOException {
        for (int i = 0; i < background.size(); i++) {
            assertTrue(background.get(i).isAlive(), "a background command ended early:\n" + tail(logs.get(i)));
        }
    }

    Path folder() {
        return folder;
    }

    @Override
    public void close() {
        for (int i = background.size() - 1; i >= 0; i--) {
            destroy(background.get(i));
        }
    }

    private static void destroy(Process process) {
        process.descendants().forEach(ProcessHandle::destroy);
        process.destroy();
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.descendants().forEach(ProcessHandle::destroyForcibly);
                process.destroyForcibly();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    static String tail(Path log) throws IOException {
        List<String> lines = Files.exists(log) ? Files.readAllLines(log, StandardCharsets.UTF_8) : List.of();
        return String.join("\n", lines.subList(Math.max(0, lines.size() - 30), lines.size()));
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0)) {
            return socket.getLocalPort();
        }
    }
}
