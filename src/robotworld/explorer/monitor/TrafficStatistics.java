package robotworld.explorer.monitor;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import robotworld.observe.AnswerSeen;
import robotworld.observe.Gap;
import robotworld.observe.Liveness;
import robotworld.observe.ModuleRef;
import robotworld.observe.QueueLength;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldObserver;

/**
 * Counts what a world's modules do, for the status strip and the console's compact mode: per module the queue
 * length, the calls (answers) per second over the last {@value #RATE_SECONDS} s, the errors, the median latency of
 * the last {@value #LATENCIES} remote calls and the last answer; per participant its liveness. Fed by a
 * {@link robotworld.observe.WorldTap}, read from any thread as {@link #snapshot() snapshots}.
 */
public final class TrafficStatistics implements WorldObserver {

    /** The span the call rate is averaged over. */
    public static final int RATE_SECONDS = 5;
    /** How many latencies the median is taken of. */
    public static final int LATENCIES = 64;

    private final Map<ModuleRef, Counter> modules = new LinkedHashMap<>();
    private final Map<String, Liveness> liveness = new LinkedHashMap<>();
    private long gaps;

    /** Counters for the modules of {@code layout}. */
    public TrafficStatistics(WorldLayout layout) {
        for (WorldLayout.Participant participant : layout.participants()) {
            liveness.put(participant.name(), new Liveness(participant.name(), Liveness.State.UNKNOWN, null,
                    "not watching yet"));
            for (ModuleRef module : participant.modules()) {
                modules.put(module, new Counter());
            }
        }
    }

    /**
     * One module's figures.
     *
     * @param module       the module
     * @param queued       requests waiting
     * @param callsPerSecond answers per second over the last {@value #RATE_SECONDS} s
     * @param calls        answers since watching started
     * @param errors       error answers since watching started
     * @param medianLatency median of the recent known latencies, or null
     * @param lastAnswer   the newest answer's function and values in words, or empty
     * @param lastAt       when it came, or null
     */
    public record ModuleFigures(ModuleRef module, int queued, double callsPerSecond, long calls, long errors,
                                Duration medianLatency, String lastAnswer, Instant lastAt) {
    }

    /**
     * Everything at one moment.
     *
     * @param modules      per module, in layout order
     * @param participants per participant, in layout order
     * @param gaps         how often events were missed
     */
    public record Snapshot(List<ModuleFigures> modules, List<Liveness> participants, long gaps) {
    }

    /** The figures now. */
    public synchronized Snapshot snapshot() {
        long now = System.nanoTime();
        List<ModuleFigures> figures = new ArrayList<>();
        for (Map.Entry<ModuleRef, Counter> entry : modules.entrySet()) {
            Counter c = entry.getValue();
            figures.add(new ModuleFigures(entry.getKey(), c.queued, c.rate(now), c.calls, c.errors, c.median(),
                    c.lastAnswer, c.lastAt));
        }
        return new Snapshot(figures, new ArrayList<>(liveness.values()), gaps);
    }

    @Override
    public synchronized void queueLength(QueueLength event) {
        Counter counter = modules.get(event.module());
        if (counter != null) {
            counter.queued = event.queued();
        }
    }

    @Override
    public synchronized void answerSeen(AnswerSeen event) {
        Counter counter = modules.get(event.module());
        if (counter == null) {
            return;
        }
        counter.lastAnswer = robotworld.explorer.monitor.logic.xvsm.AnswerText.function(event.answer()) + " "
                + robotworld.explorer.monitor.logic.xvsm.AnswerText.value(event.module().moduleClass(),
                event.answer());
        counter.lastAt = event.at();
        if (event.earlier()) {
            return;
        }
        counter.calls++;
        counter.count(System.nanoTime());
        if (event.isError()) {
            counter.errors++;
        }
        if (event.latency() != null) {
            counter.latencies[counter.latencyCount++ % LATENCIES] = event.latency().toNanos();
        }
    }

    @Override
    public synchronized void liveness(Liveness event) {
        liveness.put(event.participant(), event);
    }

    @Override
    public synchronized void gap(Gap gap) {
        gaps++;
    }

    /** One module's counters: calls per second in one-second buckets. */
    private static final class Counter {
        private final long[] buckets = new long[RATE_SECONDS + 1];
        private final long[] bucketSecond = new long[RATE_SECONDS + 1];
        private final long[] latencies = new long[LATENCIES];
        private int latencyCount;
        private int queued;
        private long calls;
        private long errors;
        private String lastAnswer = "";
        private Instant lastAt;

        void count(long nanos) {
            long second = nanos / 1_000_000_000L;
            int index = (int) Math.floorMod(second, (long) buckets.length);
            if (bucketSecond[index] != second) {
                bucketSecond[index] = second;
                buckets[index] = 0;
            }
            buckets[index]++;
        }

        /** Answers per second over the last full seconds. */
        double rate(long nanos) {
            long current = nanos / 1_000_000_000L;
            long sum = 0;
            for (int i = 0; i < buckets.length; i++) {
                long age = current - bucketSecond[i];
                if (age >= 1 && age <= RATE_SECONDS) {
                    sum += buckets[i];
                }
            }
            return sum / (double) RATE_SECONDS;
        }

        Duration median() {
            int n = Math.min(latencyCount, LATENCIES);
            if (n == 0) {
                return null;
            }
            long[] sorted = Arrays.copyOf(latencies, n);
            Arrays.sort(sorted);
            return Duration.ofNanos(sorted[(n - 1) / 2]);
        }
    }
}
