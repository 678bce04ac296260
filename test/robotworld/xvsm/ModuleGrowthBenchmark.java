package robotworld.xvsm;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;

import robotworld.core.BumperModule;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;

/**
 * What a world's size costs ({@code ./antw bench-remote}, after the space figures): one space server, one provider
 * program serving {@code N} bumper modules (its own runtime and connection; every module waiting for requests), and
 * one caller program calling a random one of them, for N = 1, 100 and 1 000 ({@code bench.growth.modules}). Prints
 * the module-call p50 and p99 for each N (median of {@code bench.growth.runs} runs of {@code bench.growth.calls}
 * calls) and the threads of the process by role, taken while every module waits, after the threads started for the
 * start-up burst have ended (21 s, {@code bench.growth.settleMillis}): the server's ({@code space-server*}), the
 * space clients' ({@code space-client*}) and the Local sides' ({@code xvsm-serve*}). The verdict then compares the
 * largest N with the smallest in {@code bench.growth.rounds} rounds (5), each measuring both in turn, by the medians of
 * the rounds' ratios: a single measurement of the smallest swings with the JIT and the machine (one-module p50s of
 * 79 to 155 us in consecutive runs).
 */
public final class ModuleGrowthBenchmark {

    private static final int[] SIZES = Arrays.stream(System.getProperty("bench.growth.modules", "1,100,1000")
            .split(",")).mapToInt(s -> Integer.parseInt(s.trim())).toArray();
    private static final int RUNS = Integer.getInteger("bench.growth.runs", 5);
    private static final int CALLS = Integer.getInteger("bench.growth.calls", 2_000);
    private static final long WARMUP_MILLIS = Long.getLong("bench.growth.warmupMillis", 4_000);
    private static final long SETTLE_MILLIS = Long.getLong("bench.growth.settleMillis", 21_000);
    private static final int ROUNDS = Integer.getInteger("bench.growth.rounds", 5);

    private ModuleGrowthBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        System.out.printf(Locale.ROOT, "%nModule calls as the world grows: one provider serving N bumper modules, one"
                + " caller; %d runs x %d calls per N%n%n", RUNS, CALLS);
        System.out.printf(Locale.ROOT, "%8s %10s %10s   %s%n", "modules", "p50 us", "p99 us",
                "threads while all wait: server / space clients / serving / whole process");
        double[] first = null;
        double[] last = null;
        for (int size : SIZES) {
            double[] row = measure(size, SETTLE_MILLIS);
            if (first == null) {
                first = row;
            }
            last = row;
            System.out.printf(Locale.ROOT, "%8d %10.0f %10.0f   %d / %d / %d / %d%n", size, row[0], row[1],
                    (int) row[2], (int) row[3], (int) row[4], (int) row[5]);
        }
        if (SIZES.length > 1) {
            int smallest = SIZES[0];
            int largest = SIZES[SIZES.length - 1];
            System.out.printf(Locale.ROOT, "%n%d modules against %d, measured in turn (%d rounds; thread counts not"
                    + " taken):%n", largest, smallest, ROUNDS);
            List<Double> p50Ratios = new ArrayList<>();
            List<Double> p99Ratios = new ArrayList<>();
            for (int round = 1; round <= ROUNDS; round++) {
                double[] small = measure(smallest, 2_000);
                double[] large = measure(largest, 2_000);
                p50Ratios.add(large[0] / small[0]);
                p99Ratios.add(large[1] / small[1]);
                System.out.printf(Locale.ROOT, "  round %d: p50 %.0f against %.0f us (%.2f x), p99 %.0f against %.0f"
                        + " us (%.2f x)%n", round, large[0], small[0], large[0] / small[0], large[1], small[1],
                        large[1] / small[1]);
            }
            double p50 = median(p50Ratios);
            double p99 = median(p99Ratios);
            System.out.printf(Locale.ROOT, "%n%d modules against %d (medians of the rounds' ratios): p50 %.2f x (target"
                    + " <= 1.2: %s), p99 %.2f x (target <= 2: %s); threads %d against %d%n", largest, smallest, p50,
                    p50 <= 1.2 ? "met" : "NOT met", p99, p99 <= 2 ? "met" : "NOT met", (int) last[5], (int) first[5]);
        }
    }

    /** {p50 us, p99 us, server threads, client threads, serving threads, all threads} for {@code size} modules. */
    private static double[] measure(int size, long settleMillis) throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0));
             XVSMRuntime provider = XVSMRuntime.using(RemoteSpace.open(server.uri()), "robot-pc", true);
             XVSMRuntime caller = XVSMRuntime.using(RemoteSpace.open(server.uri()), "laptop", true)) {
            List<XVSMBumperModuleRemote> remotes = new ArrayList<>();
            for (int m = 0; m < size; m++) {
                new XVSMBumperModuleLocal(provider, "Robot", "Bumper" + m, new FixedBumper(m));
                remotes.add(new XVSMBumperModuleRemote(caller, "Robot", "Bumper" + m));
            }
            long warmUntil = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WARMUP_MILLIS);
            while (System.nanoTime() < warmUntil) {
                callRandom(remotes);
            }
            // threads the server started for the start-up burst (a thousand connections accepted at once) end
            // after 10 s idle, a few at a time: after 11 s some were still there (30 threads against 23)
            Thread.sleep(settleMillis);
            Map<String, Integer> threads = threadsByRole();
            List<Double> p50s = new ArrayList<>();
            List<Double> p99s = new ArrayList<>();
            for (int run = 0; run < RUNS; run++) {
                long[] samples = new long[CALLS];
                for (int i = 0; i < CALLS; i++) {
                    long start = System.nanoTime();
                    callRandom(remotes);
                    samples[i] = System.nanoTime() - start;
                }
                Arrays.sort(samples);
                p50s.add(samples[CALLS / 2] / 1e3);
                p99s.add(samples[(int) (CALLS * 0.99)] / 1e3);
            }
            return new double[] {median(p50s), median(p99s), threads.getOrDefault("server", 0),
                    threads.getOrDefault("client", 0), threads.getOrDefault("serving", 0), threads.get("all")};
        }
    }

    private static void callRandom(List<XVSMBumperModuleRemote> remotes) {
        int module = ThreadLocalRandom.current().nextInt(remotes.size());
        int mask = remotes.get(module).getAllBumper();
        if (mask != (module & 0xFF)) {
            throw new IllegalStateException("module " + module + " answered " + mask);
        }
    }

    private static Map<String, Integer> threadsByRole() {
        Map<String, Integer> counts = new TreeMap<>();
        for (Thread thread : Thread.getAllStackTraces().keySet()) {
            String name = thread.getName();
            String role = name.startsWith("space-server") ? "server" : name.startsWith("space-client") ? "client"
                    : name.startsWith("xvsm-serve") ? "serving" : "other";
            counts.merge(role, 1, Integer::sum);
            counts.merge("all", 1, Integer::sum);
        }
        if (Boolean.getBoolean("bench.growth.listThreads")) {
            System.out.println(Thread.getAllStackTraces().keySet().stream().map(Thread::getName).sorted().toList());
        }
        return counts;
    }

    private static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        sorted.sort(Double::compare);
        return sorted.get(sorted.size() / 2);
    }

    /** A bumper whose mask names its module. */
    private record FixedBumper(int module) implements BumperModule {
        @Override
        public int getAllBumper() {
            return module & 0xFF;
        }

        @Override
        public boolean getSingleBumper(int bumperNumber) {
            return (module >> (bumperNumber - 1) & 1) != 0;
        }
    }
}
