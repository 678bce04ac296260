package robotworld.testsupport;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A space server in a process of its own ({@code rwe space --port 0} in a child JVM on this class path), as it runs
 * in a lab: benchmarks that compare the space with a server that is its own process (Redis) use it, so that the
 * clients' threads and garbage do not share a heap and a collector with the server. Close it to kill the process.
 */
public final class SpaceServerProcess implements AutoCloseable {

    private static final Pattern LISTENING = Pattern.compile("listening on (http://\\S+)");

    private final Process process;
    private final URI uri;

    private SpaceServerProcess(Process process, URI uri) {
        this.process = process;
        this.uri = uri;
    }

    /** Not a JVM option: {@code --prepend-classes=<dir>} puts a directory of classes before this build's. */
    public static final String PREPEND_CLASSES = "--prepend-classes=";
    /** Not a JVM option: {@code --cpus=<list>} runs the server under {@code taskset -c <list>}. */
    public static final String ON_CPUS = "--cpus=";

    /**
     * Starts a server with the JVM options {@code jvm} (e.g. {@code -Xmx1g}, or {@link #PREPEND_CLASSES}, {@link
     * #ON_CPUS}); returns once it listens.
     */
    public static SpaceServerProcess start(List<String> jvm) throws IOException {
        List<String> command = new ArrayList<>();
        List<String> jvmOptions = new ArrayList<>();
        String classPath = System.getProperty("java.class.path");
        for (String option : jvm) {
            if (option.startsWith(ON_CPUS)) {
                command.addAll(List.of("taskset", "-c", option.substring(ON_CPUS.length())));
            } else if (option.startsWith(PREPEND_CLASSES)) {
                // another build's classes first: an A/B trial of a code change in one benchmark run
                classPath = option.substring(PREPEND_CLASSES.length()) + java.io.File.pathSeparator + classPath;
            } else {
                jvmOptions.add(option);
            }
        }
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(robotworld.program.JvmOptions.LATENCY); // as rwe starts it
        command.addAll(jvmOptions);
        command.addAll(List.of("-cp", classPath, "robotworld.explorer.cli.Rwe", "space",
                "--port", "0"));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        BufferedReader out = new BufferedReader(new InputStreamReader(process.getInputStream(),
                StandardCharsets.UTF_8));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        StringBuilder said = new StringBuilder();
        while (System.nanoTime() < deadline) {
            String line = out.readLine();
            if (line == null) {
                break;
            }
            said.append(line).append('\n');
            Matcher listening = LISTENING.matcher(line);
            if (listening.find()) {
                Thread drain = new Thread(() -> {
                    try {
                        while (out.readLine() != null) {
                            // keeps the pipe from filling
                        }
                    } catch (IOException e) {
                        // the process ended
                    }
                }, "space-server-process-output");
                drain.setDaemon(true);
                drain.start();
                return new SpaceServerProcess(process, URI.create(listening.group(1)));
            }
        }
        process.destroyForcibly();
        throw new IllegalStateException("the space server process did not start; it said:\n" + said);
    }

    /** The server process's id (for its CPU time, say). */
    public long pid() {
        return process.pid();
    }

    public URI uri() {
        return uri;
    }

    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }
}
