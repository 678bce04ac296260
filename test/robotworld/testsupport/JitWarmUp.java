package robotworld.testsupport;

import java.lang.management.CompilationMXBean;
import java.lang.management.ManagementFactory;
import java.time.Duration;

/**
 * A benchmark's warm-up that lasts until the JIT has settled, not for a fixed time. On a small machine the JIT's
 * compiler threads share the CPUs with the code being measured: confined to one CPU, the remote-space benchmark
 * still spent a large share of its time in C2 compilations after 30 s (methods such as the request parser took
 * about a second each to compile, some several times after deoptimizations), and figures taken then swing between
 * two regimes as the compile queue drains. So the warm-up repeats its pass until one pass spent at most a small
 * share of its time compiling, twice in a row, within a bound.
 */
public final class JitWarmUp {

    /** What a warm-up did: how long it took, and whether the JIT settled within the bound. */
    public record Outcome(Duration took, int passes, double lastCompileShare, boolean settled) {
        @Override
        public String toString() {
            return String.format("warm-up %.0f s, %d passes, JIT %s (%.1f %% of the last pass compiling)",
                    took.toMillis() / 1e3, passes, settled ? "settled" : "NOT settled within the bound",
                    lastCompileShare * 100);
        }
    }

    /** One pass of the workload to warm up. */
    public interface Pass {
        void run() throws Exception;
    }

    private static final CompilationMXBean JIT = ManagementFactory.getCompilationMXBean();

    private JitWarmUp() {
    }

    /**
     * Runs {@code pass} for at least {@code least}, then on until two passes in a row spent at most {@code
     * quietShare} of their time compiling, or until {@code most}.
     */
    public static Outcome run(Duration least, Duration most, double quietShare, Pass pass) throws Exception {
        long start = System.nanoTime();
        int passes = 0;
        int quietInARow = 0;
        double share = Double.NaN;
        while (true) {
            long compiledBefore = compileMillis();
            long passStart = System.nanoTime();
            pass.run();
            passes++;
            long passMillis = Math.max(1, (System.nanoTime() - passStart) / 1_000_000);
            share = (compileMillis() - compiledBefore) / (double) passMillis;
            quietInARow = share <= quietShare ? quietInARow + 1 : 0;
            Duration took = Duration.ofNanos(System.nanoTime() - start);
            if (took.compareTo(least) >= 0 && (quietInARow >= 2 || took.compareTo(most) >= 0)) {
                return new Outcome(took, passes, share, quietInARow >= 2);
            }
        }
    }

    /** The JIT's total compile time so far, in ms (all compiler threads), or 0 where the JVM does not tell. */
    public static long compileMillis() {
        return JIT != null && JIT.isCompilationTimeMonitoringSupported() ? JIT.getTotalCompilationTime() : 0;
    }
}
