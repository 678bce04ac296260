package robotworld.safety;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A program in a JVM of its own, on this JVM's class path, with its output in a log file: the programs whose
 * deaths the safety tests and benchmarks cause (SIGTERM, SIGKILL, System.exit).
 */
final class ChildProgram implements AutoCloseable {

    private final Process process;
    private final Path log;

    private ChildProgram(Process process, Path log) {
        this.process = process;
        this.log = log;
    }

    /** Starts {@code mainClass} with {@code args}; {@code properties} are {@code -Dkey=value} options. */
    static ChildProgram start(Path directory, List<String> properties, Class<?> mainClass, String... args)
            throws IOException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-Xmx128m");
        command.add("-XX:TieredStopAtLevel=1");
        if (properties.stream().noneMatch(p -> p.startsWith("-D" + robotworld.bus.BusTiming.RESPONSE_TIMEOUT_PROPERTY))) {
            // no safety test is about a module's reply time: a child starved of CPU on a busy machine must not fail
            // its first bus call after 3 x 100 ms
            command.add("-D" + robotworld.bus.BusTiming.RESPONSE_TIMEOUT_PROPERTY + "=2000");
        }
        command.addAll(properties);
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(mainClass.getName());
        command.addAll(List.of(args));
        Files.createDirectories(directory);
        Path log = Files.createTempFile(directory, mainClass.getSimpleName(), ".log");
        Process process = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        return new ChildProgram(process, log);
    }

    /** Waits until the program has printed a line starting with {@code prefix}. */
    void awaitLine(String prefix, Duration limit) throws InterruptedException {
        long deadline = System.nanoTime() + limit.toNanos();
        while (output().lines().noneMatch(line -> line.startsWith(prefix))) {
            if (!process.isAlive()) {
                throw new IllegalStateException("the program ended (exit code " + process.exitValue()
                        + ") before printing '" + prefix + "'; its output:\n" + output());
            }
            if (System.nanoTime() - deadline > 0) {
                throw new IllegalStateException("the program did not print '" + prefix + "' within "
                        + limit.toMillis() + " ms; its output:\n" + output());
            }
            Thread.sleep(5);
        }
    }

    /** SIGTERM, as Ctrl-C or a service manager would stop it. */
    void terminate() {
        process.destroy();
    }

    /** SIGKILL: no shutdown hook runs, nothing is cleaned up. */
    void kill() {
        process.destroyForcibly();
    }

    /** Waits for the program to end; returns its exit code. */
    int awaitExit(Duration limit) throws InterruptedException {
        if (!process.waitFor(limit.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new IllegalStateException("the program did not end within " + limit.toMillis() + " ms; its output:\n"
                    + output());
        }
        return process.exitValue();
    }

    boolean isAlive() {
        return process.isAlive();
    }

    long pid() {
        return process.pid();
    }

    /** Everything the program printed so far. */
    String output() {
        try {
            return Files.readString(log);
        } catch (IOException e) {
            return "(no output: " + e.getMessage() + ")";
        }
    }

    @Override
    public void close() {
        if (process.isAlive()) {
            process.destroyForcibly();
            try {
                process.waitFor(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    @Override
    public String toString() {
        return "ChildProgram[pid " + process.pid() + ", log " + log + File.separator + "]";
    }
}
