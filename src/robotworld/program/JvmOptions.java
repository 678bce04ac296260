package robotworld.program;

import java.util.List;

/**
 * The JVM options every process of a world is started with: the {@code rwe} command line, a generated project's
 * {@code ant run}, the demo's programs and cluster members. {@code rwe} lets {@code RWE_JAVA_OPTS} override them
 * (options given later win).
 *
 * <p>{@code -XX:G1ConcRefinementThreads=0}: G1 records every write of a reference into a long-lived object (a
 * module's containers, its connection, its waiting call) as a dirty card, and by default its refinement thread
 * works those off in bursts of about a millisecond whenever enough have piled up. A world with a thousand modules
 * dirties a different card for each module it calls, so on a two-core machine such a burst came every 10 ms or so
 * and held up the call that was running: the module-call p99 went from about 0.2 ms to 0.8 ms. With no refinement
 * threads the cards are worked off in the young collection's pause instead, which did not grow measurably. Other
 * collectors ignore the option. Figures: {@code docs/benchmarks.md}, "G1's refinement bursts".
 */
public final class JvmOptions {

    /** Options for low tail latency of module calls; see the class comment. */
    public static final List<String> LATENCY = List.of("-XX:G1ConcRefinementThreads=0");

    private JvmOptions() {
    }
}
