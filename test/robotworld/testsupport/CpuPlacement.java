package robotworld.testsupport;

import java.io.File;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Runs the latency part of a benchmark a second time with every thread on one CPU.
 *
 * <p>Why: on a small virtual machine a thread woken on another CPU costs about 20 µs more than one woken on
 * the same CPU (the idle vCPU has to be kicked awake). The two threads of a TCP echo land on the same CPU or on
 * different ones at random, so the baseline flips between ~14 µs and ~50 µs from run to run, while a chain of
 * four or more threads (client, server, second client) always crosses CPUs somewhere. A ratio of the two then
 * measures thread placement, not software. Confined to one CPU ({@code taskset -c 0}), both pay the same cheap
 * same-CPU switches and the ratio shows what the software adds; the benchmarks print both placements.
 */
public final class CpuPlacement {

    /** Set in the confined child JVM. */
    private static final String CONFINED_PROPERTY = "bench.oneCpu";

    private CpuPlacement() {
    }

    /** Whether this JVM is the confined re-run. */
    public static boolean isConfined() {
        return Boolean.getBoolean(CONFINED_PROPERTY);
    }

    /** How this JVM's threads are placed, for the benchmark's printout. */
    public static String describe() {
        int cpus = Runtime.getRuntime().availableProcessors();
        return isConfined() ? "all threads on one CPU (taskset -c 0)"
                : String.format(Locale.ROOT, "threads placed by the OS on %d CPU%s", cpus, cpus == 1 ? "" : "s");
    }

    /**
     * Runs {@code main} with {@code args} in a child JVM confined to CPU 0, its output going to this one's, and
     * waits for it. Returns false, saying why, where that cannot be done (no {@code taskset}, one CPU only).
     */
    public static boolean runConfined(Class<?> main, String... args) throws IOException, InterruptedException {
        Path taskset = onPath("taskset");
        if (taskset == null) {
            System.out.println("(no one-CPU re-run: taskset is not installed; it is part of util-linux)");
            return false;
        }
        if (Runtime.getRuntime().availableProcessors() < 2) {
            return false; // this run is already on one CPU
        }
        List<String> command = new ArrayList<>(List.of(taskset.toString(), "-c", "0",
                Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        for (String argument : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (argument.startsWith("-D") || argument.startsWith("-Xm") || argument.startsWith("--add-")) {
                command.add(argument); // bench.* settings, the heap size, access to JDK internals (Hazelcast)
            }
        }
        command.add("-D" + CONFINED_PROPERTY + "=true");
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(main.getName());
        command.addAll(List.of(args));
        Process child = new ProcessBuilder(command).inheritIO().start();
        int exit = child.waitFor();
        if (exit != 0) {
            throw new IllegalStateException("the one-CPU re-run failed with exit code " + exit);
        }
        return true;
    }

    private static Path onPath(String program) {
        String path = System.getenv("PATH");
        if (path == null) {
            return null;
        }
        for (String directory : path.split(File.pathSeparator)) {
            Path candidate = Path.of(directory, program);
            if (Files.isExecutable(candidate)) {
                return candidate;
            }
        }
        return null;
    }
}
