package robotworld.xvsm;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import robotworld.core.IRDistanceModule;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;

/**
 * Caller soak ({@code ./antw bench-soak}): many concurrent module callers on one space server, with providers
 * serving, first with {@code bench.soak.baseCallers} (200) callers, then with {@code bench.soak.callers} (1 000),
 * each for {@code bench.soak.seconds} (60). Callers are spread over {@code bench.soak.hosts} (50) computers, each
 * its own runtime and connection pool, and call {@code getSingleSensor} on {@code bench.soak.modules} (8) IR
 * modules, each served by its own providing runtime; every answer names its module and sensor, so an answer
 * meant for another call is counted as a mismatch.
 *
 * <p>Prints calls/s, latency percentiles, failures by kind, mismatches, serving threads that died and the
 * process's thread count, and the verdict: throughput at the high caller count within 20 % of the base figure,
 * no mismatch, no dead serving thread.
 */
public final class CallerSoak {

    private static final int BASE_CALLERS = Integer.getInteger("bench.soak.baseCallers", 200);
    private static final int CALLERS = Integer.getInteger("bench.soak.callers", 1_000);
    private static final int HOSTS = Integer.getInteger("bench.soak.hosts", 50);
    private static final int MODULES = Integer.getInteger("bench.soak.modules", 8);
    private static final int SECONDS = Integer.getInteger("bench.soak.seconds", 60);
    private static final Duration CALL_TIMEOUT = Duration.ofSeconds(10);

    private CallerSoak() {
    }

    /** What one phase measured. */
    private record Phase(int callers, double callsPerSecond, long p50Micros, long p99Micros, long maxMicros,
                         Map<String, Long> failures, long mismatches, int deadServers, int threads) {
    }

    public static void main(String[] args) throws Exception {
        System.out.printf(Locale.ROOT, "Caller soak: %d IR modules on one space server, callers on %d computers, "
                + "%d s per phase, %s, Java %s, %d CPUs%n%n", MODULES, HOSTS, SECONDS, System.getProperty("os.name"),
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors());
        try (EmbeddedSpace space = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0))) {
            List<XVSMRuntime> providers = new ArrayList<>();
            List<XVSMIRDistanceModuleLocal> locals = new ArrayList<>();
            for (int m = 0; m < MODULES; m++) {
                XVSMRuntime provider = XVSMRuntime.using(RemoteSpace.open(server.uri()), "robot-" + m, true);
                providers.add(provider);
                locals.add(new XVSMIRDistanceModuleLocal(provider, "Robot" + m, "IR", new NamedDistances(m), false));
            }
            try {
                Phase base = phase(server, BASE_CALLERS, locals);
                Phase high = phase(server, CALLERS, locals);
                double ratio = high.callsPerSecond / base.callsPerSecond;
                boolean clean = high.mismatches + base.mismatches == 0 && high.deadServers + base.deadServers == 0;
                System.out.printf(Locale.ROOT, "%d callers reach %.2f x the calls/s of %d callers (target >= 0.80): "
                        + "%s; mismatches %d, dead serving threads %d: %s%n", CALLERS, ratio, BASE_CALLERS,
                        ratio >= 0.8 ? "met" : "NOT met", base.mismatches + high.mismatches,
                        base.deadServers + high.deadServers, clean ? "met" : "NOT met");
            } finally {
                providers.forEach(XVSMRuntime::close);
            }
        }
    }

    private static Phase phase(SpaceServer server, int callers, List<XVSMIRDistanceModuleLocal> locals)
            throws Exception {
        List<XVSMRuntime> hosts = new ArrayList<>();
        for (int h = 0; h < HOSTS; h++) {
            hosts.add(XVSMRuntime.using(RemoteSpace.open(server.uri()), "host-" + h, true));
        }
        LongAdder calls = new LongAdder();
        AtomicLong mismatches = new AtomicLong();
        Map<String, LongAdder> failures = new ConcurrentHashMap<>();
        long[][] latencies = new long[callers][];
        AtomicBoolean measuring = new AtomicBoolean();
        AtomicBoolean running = new AtomicBoolean(true);
        CountDownLatch finished = new CountDownLatch(callers);
        List<Thread> threads = new ArrayList<>();
        for (int c = 0; c < callers; c++) {
            int caller = c;
            XVSMRuntime host = hosts.get(c % HOSTS);
            List<XVSMIRDistanceModuleRemote> modules = new ArrayList<>();
            for (int m = 0; m < locals.size(); m++) {
                XVSMIRDistanceModuleRemote remote = new XVSMIRDistanceModuleRemote(host, "Robot" + m, "IR");
                remote.setCallTimeout(CALL_TIMEOUT);
                modules.add(remote);
            }
            Thread thread = new Thread(() -> {
                // small at first: a 512 KB array per caller is a humongous object for G1 and would, for a
                // thousand callers, take half the heap and tax the high phase with collections of its own making
                long[] mine = new long[1 << 10];
                int count = 0;
                try {
                    while (running.get()) {
                        int module = ThreadLocalRandom.current().nextInt(modules.size());
                        int sensor = 1 + ThreadLocalRandom.current().nextInt(IRDistanceModule.SENSORS);
                        long started = System.nanoTime();
                        try {
                            int distance = modules.get(module).getSingleSensor(sensor);
                            if (distance != NamedDistances.distance(module, sensor)) {
                                mismatches.incrementAndGet();
                            }
                            if (measuring.get()) {
                                calls.increment();
                                if (count == mine.length) {
                                    mine = Arrays.copyOf(mine, count * 2);
                                }
                                mine[count++] = System.nanoTime() - started;
                            }
                        } catch (RuntimeException e) {
                            if (measuring.get()) {
                                failures.computeIfAbsent(e.getClass().getSimpleName(), k -> new LongAdder()).increment();
                            }
                        }
                    }
                } finally {
                    latencies[caller] = Arrays.copyOf(mine, count);
                    finished.countDown();
                }
            }, "soak-caller-" + c);
            thread.setDaemon(true);
            threads.add(thread);
        }
        threads.forEach(Thread::start);
        long warmUp = Math.max(5, SECONDS / 6);
        System.out.printf(Locale.ROOT, "%d callers: warming up %d s, then measuring %d s ", callers, warmUp, SECONDS);
        Thread.sleep(TimeUnit.SECONDS.toMillis(warmUp));
        measuring.set(true);
        long started = System.nanoTime();
        int peakThreads = 0;
        for (int s = 0; s < SECONDS; s++) {
            Thread.sleep(1_000);
            peakThreads = Math.max(peakThreads, Thread.activeCount());
            if (s % 10 == 9) {
                System.out.print('.');
                System.out.flush();
            }
        }
        measuring.set(false);
        double seconds = (System.nanoTime() - started) / 1e9;
        running.set(false);
        finished.await(CALL_TIMEOUT.toSeconds() + 30, TimeUnit.SECONDS);
        hosts.forEach(XVSMRuntime::close);

        long[] all = Arrays.stream(latencies).filter(l -> l != null).flatMapToLong(Arrays::stream).sorted().toArray();
        int dead = (int) locals.stream().filter(local -> !local.isServing()).count();
        Map<String, Long> failed = new ConcurrentHashMap<>();
        failures.forEach((kind, n) -> failed.put(kind, n.sum()));
        Phase phase = new Phase(callers, calls.sum() / seconds, percentile(all, 50), percentile(all, 99),
                all.length == 0 ? 0 : all[all.length - 1] / 1_000, failed, mismatches.get(), dead, peakThreads);
        System.out.printf(Locale.ROOT, "%n  %,.0f calls/s, p50 %,d us, p99 %,d us, max %,d us; failures %s; "
                + "mismatches %d; dead serving threads %d; peak threads in this process %d%n%n",
                phase.callsPerSecond, phase.p50Micros, phase.p99Micros, phase.maxMicros,
                failed.isEmpty() ? "none" : failed, phase.mismatches, phase.deadServers, phase.threads);
        return phase;
    }

    private static long percentile(long[] sorted, int percent) {
        if (sorted.length == 0) {
            return 0;
        }
        return sorted[Math.min(sorted.length - 1, (int) ((long) sorted.length * percent / 100))] / 1_000;
    }

    /** IR distances that name their module and sensor: module * 100 + sensor (also for the cluster's kill soak). */
    public static final class NamedDistances implements IRDistanceModule {
        private final int module;

        public NamedDistances(int module) {
            this.module = module;
        }

        public static int distance(int module, int sensor) {
            return module * 100 + sensor;
        }

        @Override
        public String getAllSensors() {
            StringBuilder text = new StringBuilder();
            for (int sensor = 1; sensor <= SENSORS; sensor++) {
                text.append(sensor == 1 ? "" : " ").append(distance(module, sensor));
            }
            return text.toString();
        }

        @Override
        public int[] getAllSensors_ByteRep() {
            int[] bytes = new int[SENSORS];
            Arrays.fill(bytes, module);
            return bytes;
        }

        @Override
        public int getSingleSensor_Cached(int sensorNr) {
            return distance(module, sensorNr);
        }

        @Override
        public int getSingleSensor(int sensorNr) {
            return distance(module, sensorNr);
        }
    }
}
