package robotworld.xvsm;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import robotworld.testsupport.CpuPlacement;
import robotworld.testsupport.TcpEcho;
import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.core.BumperModule;
import robotworld.sim.robot.LineTiming;
import robotworld.sim.robot.SimRobotConfig;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.ProjectFiles;

/**
 * Runtime benchmark ({@code ./antw bench-runtime}): a bumper read through the XVSM proxies and a space server on
 * loopback, against a local read and against a plain TCP loopback round trip measured in the same run.
 * <ol>
 * <li>One requester: p50/p99 of a local read (publishing off, and on), of one bare space operation over HTTP,
 *     and of a remote read; the TCP loopback round trip of a small message alongside; target: remote p50 at most
 *     8 times the TCP round trip.</li>
 * <li>20 concurrent requesters (20 hosts, each its own connection): remote read p50/p99, throughput and hardware
 *     reads per call, without and with adaptive batching.</li>
 * </ol>
 * The simulated robot is {@code docs/examples/simulated-robot.sim} at fast timing, on {@code tcp://} with no
 * frame gap (a simulator link), so the bus adds as little as possible and the space path shows. Everything runs
 * for {@code bench.warmupSeconds} (10) first. The one-requester part runs twice: in a child JVM with every thread
 * on one CPU, and with threads placed by the OS (see {@link CpuPlacement} for why); argument {@code single}
 * runs only that part. Properties: {@code bench.runs}, {@code bench.calls},
 * {@code bench.concurrentRuns}, {@code bench.callsPerRequester}.
 */
public final class RuntimeBenchmark {

    private static final int RUNS = Integer.getInteger("bench.runs", 7);
    private static final int CALLS = Integer.getInteger("bench.calls", 1000);
    private static final int REQUESTERS = 20;
    /** The JIT needs tens of thousands of calls on a small machine before the HTTP path settles. */
    private static final long WARMUP_SECONDS = Long.getLong("bench.warmupSeconds", 10);
    private static final int CONCURRENT_RUNS = Integer.getInteger("bench.concurrentRuns", 5);
    private static final int CALLS_PER_REQUESTER = Integer.getInteger("bench.callsPerRequester", 200);
    private static final double TARGET_RATIO = 8.0;

    private RuntimeBenchmark() {
    }

    /** What one requester-thread measurement gives: latencies in ns. */
    private interface Call {
        void run() throws Exception;
    }

    public static void main(String[] args) throws Exception {
        boolean singleOnly = Arrays.asList(args).contains("single");
        if (!CpuPlacement.isConfined()) {
            System.out.printf(Locale.ROOT, "XVSM runtime benchmark, %s, Java %s, %d CPUs%n%n",
                    System.getProperty("os.name"), System.getProperty("java.version"),
                    Runtime.getRuntime().availableProcessors());
            if (!singleOnly) {
                CpuPlacement.runConfined(RuntimeBenchmark.class, "single");
            }
        }
        SimRobotConfig config = SimRobotConfigReader.read(ProjectFiles.resolve("docs/examples/simulated-robot.sim"))
                .withTiming(LineTiming.FAST);
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0));
             SimulatedRobot robot = SimulatedRobot.create(config);
             RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(config.baud()),
                     BusTiming.defaults().withFrameGap(Duration.ZERO));
             TcpEcho echo = new TcpEcho(64, 64);
             XVSMRuntime provider = XVSMRuntime.using(RemoteSpace.open(server.uri()), "robot-pc", true)) {
            CountingBumper hardware = new CountingBumper(new BumperModuleProxy(bus, 2, "Bumper"));
            XVSMBumperModuleLocal local = new XVSMBumperModuleLocal(provider, "Robot", "Bumper", hardware, false);
            singleRequester(server, local, echo);
            if (!singleOnly) {
                concurrentRequesters(server, local, hardware, echo, false);
                concurrentRequesters(server, local, hardware, echo, true);
            }
        }
    }

    private static void singleRequester(SpaceServer server, XVSMBumperModuleLocal local, TcpEcho echo)
            throws Exception {
        try (XVSMRuntime laptop = XVSMRuntime.using(RemoteSpace.open(server.uri()), "laptop", true)) {
            XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, "Robot", "Bumper");
            Capi space = laptop.space();
            ContainerRef answers = remote.answerContainer();
            Call bareOperation = () -> space.read(answers, Timeout.TRY_ONCE, Selector.key("nobody", Selector.ALL));
            Call tcp = echo::roundTrip;
            Call localRead = local::getAllBumper;
            Call remoteRead = remote::getAllBumper;

            warmUp(List.of(localRead, bareOperation, remoteRead, tcp));
            double[][] quietTcp = alone(tcp);
            local.setPublishLocalCalls(false);
            double[][] localOff = alternating(localRead, tcp);
            local.setPublishLocalCalls(true);
            double[][] localOn = alternating(localRead, tcp);
            local.runtime().awaitPublished(Duration.ofSeconds(10));
            double[][] bare = alternating(bareOperation, tcp);
            double[][] remoteRound = alternating(remoteRead, tcp);
            double baseline = median(quietTcp[0]);

            System.out.printf(Locale.ROOT, "One requester, %s: getAllBumper, %d runs x %d calls, medians of the "
                    + "run percentiles (us)%n", CpuPlacement.describe(), RUNS, CALLS);
            System.out.printf(Locale.ROOT, "  TCP loopback round trip (64 bytes each way), measured alone: p50 %.1f, "
                    + "p99 %.1f%n", baseline, median(quietTcp[1]));
            System.out.printf(Locale.ROOT, "  %-50s %8s %8s %9s %13s%n", "", "p50", "p99", "x TCP p50",
                    "TCP p50 alt.");
            row("local read, publishing off", localOff, baseline);
            row("local read, publishing on (asynchronous)", localOn, baseline);
            row("one space operation over HTTP (read, try once)", bare, baseline);
            row("remote read through the space server", remoteRound, baseline);
            double ratio = median(remoteRound[0]) / baseline;
            System.out.printf(Locale.ROOT, "  target: remote p50 <= %.0f x the TCP round trip measured alone: %s "
                    + "(%.1f x; %s)%n", TARGET_RATIO, ratio <= TARGET_RATIO ? "met" : "NOT met", ratio,
                    CpuPlacement.describe());
            System.out.printf(Locale.ROOT, "  (\"TCP p50 alt.\": the TCP round trip measured alternately with the "
                    + "call; higher, as it shares the CPUs with the call's after-work)%n%n");
        }
    }

    /** Runs the calls in turn for {@value #WARMUP_SECONDS} s (property {@code bench.warmupSeconds}). */
    private static void warmUp(List<Call> calls) throws Exception {
        long end = System.nanoTime() + WARMUP_SECONDS * 1_000_000_000L;
        while (System.nanoTime() - end < 0) {
            for (Call call : calls) {
                call.run();
            }
        }
    }

    /** p50s and p99s per run of {@code call} on its own. */
    private static double[][] alone(Call call) throws Exception {
        for (int i = 0; i < CALLS; i++) {
            call.run();
        }
        double[] p50 = new double[RUNS];
        double[] p99 = new double[RUNS];
        for (int run = 0; run < RUNS; run++) {
            long[] calls = new long[CALLS];
            for (int i = 0; i < CALLS; i++) {
                long start = System.nanoTime();
                call.run();
                calls[i] = System.nanoTime() - start;
            }
            p50[run] = percentile(calls, 50);
            p99[run] = percentile(calls, 99);
        }
        return new double[][] {p50, p99};
    }

    /** p50s, p99s and TCP p50s per run, the call and a TCP round trip measured alternately. */
    private static double[][] alternating(Call call, Call tcp) throws Exception {
        for (int i = 0; i < CALLS / 4; i++) {
            call.run();
            tcp.run();
        }
        double[] p50 = new double[RUNS];
        double[] p99 = new double[RUNS];
        double[] tcpP50 = new double[RUNS];
        for (int run = 0; run < RUNS; run++) {
            long[] calls = new long[CALLS];
            long[] echoes = new long[CALLS];
            for (int i = 0; i < CALLS; i++) {
                long start = System.nanoTime();
                call.run();
                calls[i] = System.nanoTime() - start;
                start = System.nanoTime();
                tcp.run();
                echoes[i] = System.nanoTime() - start;
            }
            p50[run] = percentile(calls, 50);
            p99[run] = percentile(calls, 99);
            tcpP50[run] = percentile(echoes, 50);
        }
        return new double[][] {p50, p99, tcpP50};
    }

    private static void concurrentRequesters(SpaceServer server, XVSMBumperModuleLocal local,
                                             CountingBumper hardware, TcpEcho echo, boolean batching)
            throws Exception {
        local.setAdaptiveBatching(batching);
        local.setPublishLocalCalls(false);
        List<XVSMRuntime> hosts = new ArrayList<>();
        try {
            List<XVSMBumperModuleRemote> remotes = new ArrayList<>();
            for (int i = 0; i < REQUESTERS; i++) {
                XVSMRuntime host = XVSMRuntime.using(RemoteSpace.open(server.uri()), "host-" + i, true);
                hosts.add(host);
                remotes.add(new XVSMBumperModuleRemote(host, "Robot", "Bumper"));
            }
            concurrentRun(remotes, CALLS_PER_REQUESTER / 4); // warm-up
            double[] p50 = new double[CONCURRENT_RUNS];
            double[] p99 = new double[CONCURRENT_RUNS];
            double[] perSecond = new double[CONCURRENT_RUNS];
            double[] readsPerCall = new double[CONCURRENT_RUNS];
            for (int run = 0; run < CONCURRENT_RUNS; run++) {
                int readsBefore = hardware.reads.get();
                long start = System.nanoTime();
                long[] latencies = concurrentRun(remotes, CALLS_PER_REQUESTER);
                double seconds = (System.nanoTime() - start) / 1e9;
                p50[run] = percentile(latencies, 50);
                p99[run] = percentile(latencies, 99);
                perSecond[run] = latencies.length / seconds;
                readsPerCall[run] = (hardware.reads.get() - readsBefore) / (double) latencies.length;
            }
            long[] echoes = new long[CALLS];
            for (int i = 0; i < CALLS; i++) {
                long start = System.nanoTime();
                echo.roundTrip();
                echoes[i] = System.nanoTime() - start;
            }
            System.out.printf(Locale.ROOT, "%d concurrent requesters (one host and connection each), adaptive batching "
                    + "%s: %d runs x %d calls per requester%n", REQUESTERS, batching ? "ON" : "off", CONCURRENT_RUNS,
                    CALLS_PER_REQUESTER);
            System.out.printf(Locale.ROOT, "  remote read p50 %.0f us, p99 %.0f us; %.0f calls/s in all; %.2f hardware "
                    + "reads per call; TCP round trip alone right after: p50 %.1f us%n%n", median(p50), median(p99),
                    median(perSecond), median(readsPerCall), percentile(echoes, 50));
        } finally {
            hosts.forEach(XVSMRuntime::close);
        }
    }

    /** Every requester does {@code calls} reads at once; returns all latencies. */
    private static long[] concurrentRun(List<XVSMBumperModuleRemote> remotes, int calls) throws Exception {
        long[] latencies = new long[remotes.size() * calls];
        AtomicInteger failures = new AtomicInteger();
        CountDownLatch go = new CountDownLatch(1);
        List<Thread> threads = new ArrayList<>();
        for (int r = 0; r < remotes.size(); r++) {
            BumperModule remote = remotes.get(r);
            int offset = r * calls;
            Thread thread = new Thread(() -> {
                try {
                    go.await();
                    for (int i = 0; i < calls; i++) {
                        long start = System.nanoTime();
                        remote.getAllBumper();
                        latencies[offset + i] = System.nanoTime() - start;
                    }
                } catch (Exception e) {
                    failures.incrementAndGet();
                }
            });
            threads.add(thread);
            thread.start();
        }
        go.countDown();
        for (Thread thread : threads) {
            thread.join();
        }
        if (failures.get() > 0) {
            throw new IllegalStateException(failures.get() + " requesters failed");
        }
        return latencies;
    }

    private static void row(String label, double[][] figures, double tcpAlone) {
        double p50 = median(figures[0]);
        System.out.printf(Locale.ROOT, "  %-50s %8.1f %8.1f %9.1f %13.1f%n", label, p50, median(figures[1]),
                p50 / tcpAlone, median(figures[2]));
    }

    /** The {@code p}th percentile in microseconds. */
    private static double percentile(long[] nanos, int p) {
        long[] sorted = nanos.clone();
        Arrays.sort(sorted);
        return sorted[Math.min(sorted.length - 1, sorted.length * p / 100)] / 1e3;
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int middle = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2;
    }
}
