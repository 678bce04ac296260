package robotworld.space.remote;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * What one run of concurrent request/answer pairs measured: throughput, latency, how evenly the pairs were served,
 * whether the slow calls came together (a pause of a whole process) or one by one, and the CPU each call cost the
 * server and the clients. The figures of several runs are combined by their medians.
 */
final class PairsRun {

    /** Width of the time bins in which slow calls are counted. */
    private static final long BIN_NANOS = 20_000_000L;

    final double callsPerSecond;
    final double p50Micros;
    final double p99Micros;
    /** Calls of the least and of the most served pair. */
    final double fewestCalls;
    final double mostCalls;
    /** Share of the calls at or above the p99 that ended in the fullest 2 % of the run's 20-ms bins. */
    final double slowCallsBunched;
    /** CPU per call in microseconds; NaN where the server is not a process of its own. */
    final double serverCpuMicros;
    final double clientCpuMicros;

    private PairsRun(double callsPerSecond, double p50Micros, double p99Micros, double fewestCalls, double mostCalls,
                     double slowCallsBunched, double serverCpuMicros, double clientCpuMicros) {
        this.callsPerSecond = callsPerSecond;
        this.p50Micros = p50Micros;
        this.p99Micros = p99Micros;
        this.fewestCalls = fewestCalls;
        this.mostCalls = mostCalls;
        this.slowCallsBunched = slowCallsBunched;
        this.serverCpuMicros = serverCpuMicros;
        this.clientCpuMicros = clientCpuMicros;
    }

    /**
     * @param latencies  per pair, each call's latency in ns
     * @param ends       per pair, when each call ended ({@link System#nanoTime})
     * @param begin      when the run began
     * @param seconds    how long it ran
     * @param serverCpu  CPU ns the server used meanwhile, or negative if unknown
     * @param clientCpu  CPU ns the clients' process used meanwhile
     */
    static PairsRun of(long[][] latencies, long[][] ends, long begin, double seconds, long serverCpu, long clientCpu) {
        long[] all = Arrays.stream(latencies).filter(x -> x != null).flatMapToLong(Arrays::stream).sorted().toArray();
        long[] perPair = Arrays.stream(latencies).mapToLong(x -> x == null ? 0 : x.length).sorted().toArray();
        long p99 = percentile(all, 0.99);
        Map<Long, Integer> bins = new TreeMap<>();
        int slow = 0;
        for (int pair = 0; pair < latencies.length; pair++) {
            for (int i = 0; latencies[pair] != null && i < latencies[pair].length; i++) {
                if (latencies[pair][i] >= p99) {
                    slow++;
                    bins.merge((ends[pair][i] - begin) / BIN_NANOS, 1, Integer::sum);
                }
            }
        }
        int fullest = Math.max(1, (int) Math.round(seconds * 1e9 / BIN_NANOS * 0.02));
        int inFullest = bins.values().stream().sorted((a, b) -> b - a).limit(fullest).mapToInt(Integer::intValue).sum();
        double calls = all.length;
        return new PairsRun(calls / seconds, percentile(all, 0.50) / 1e3, p99 / 1e3, perPair[0],
                perPair[perPair.length - 1], slow == 0 ? 0 : (double) inFullest / slow,
                serverCpu < 0 ? Double.NaN : serverCpu / 1e3 / calls, serverCpu < 0 ? Double.NaN
                : clientCpu / 1e3 / calls);
    }

    /** Each figure the median of the runs' figures. */
    static PairsRun medians(List<PairsRun> runs) {
        return new PairsRun(median(runs, r -> r.callsPerSecond), median(runs, r -> r.p50Micros),
                median(runs, r -> r.p99Micros), median(runs, r -> r.fewestCalls), median(runs, r -> r.mostCalls),
                median(runs, r -> r.slowCallsBunched), median(runs, r -> r.serverCpuMicros),
                median(runs, r -> r.clientCpuMicros));
    }

    @Override
    public String toString() {
        String cpu = Double.isNaN(serverCpuMicros) ? "" : String.format("; CPU per call: server %.0f us, clients %.0f"
                + " us", serverCpuMicros, clientCpuMicros);
        return String.format("%,.0f calls/s, p50 %.0f us, p99 %.0f us; calls per pair %,.0f to %,.0f; slow calls in"
                + " the fullest 2%% of 20-ms bins %.0f%%%s", callsPerSecond, p50Micros, p99Micros, fewestCalls,
                mostCalls, slowCallsBunched * 100, cpu);
    }

    private static long percentile(long[] sorted, double p) {
        return sorted.length == 0 ? 0 : sorted[Math.min(sorted.length - 1, (int) (p * sorted.length))];
    }

    private static double median(List<PairsRun> runs, java.util.function.ToDoubleFunction<PairsRun> figure) {
        double[] values = runs.stream().mapToDouble(figure).sorted().toArray();
        int n = values.length;
        return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
    }
}
