package robotworld.cluster;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.Timeout;
import robotworld.space.Tuple;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.CpuPlacement;
import robotworld.testsupport.TcpEcho;

/**
 * What the clustered space costs and how quickly it recovers, with one space server, an embedded space and a raw
 * TCP round trip measured in the same run as baselines:
 * <ul>
 * <li>the request/answer cycle of a module call (the caller's write-then-take, the provider's shift-then-take), as
 * programs on other computers see it: over HTTP to one space server, and over HTTP to a 3-member cluster with the
 * caller's server in front of one member and the provider's in front of another; then in-process, on an embedded
 * space and on cluster handles; median over runs of each run's p50 and p99, and of the ratio to the TCP p50
 * measured just before; in a child JVM with every thread on one CPU, then with threads placed by the OS;</li>
 * <li>50 concurrent clients (a remote client each) doing write+take cycles on their own containers, against one
 * space server and against the cluster's three servers: throughput and cycle p50/p99; the same in-process;</li>
 * <li>failover: a caller makes module calls while the member owning one of its containers crashes (Hazelcast
 * terminated: its connections close, as when its process is killed); the longest pause between two completed
 * calls, over {@code bench.kills} crashes, each on a fresh third member.</li>
 * </ul>
 * All members and servers run in this JVM on loopback. Run with {@code ./antw bench-cluster}; {@code -Dbench.runs},
 * {@code -Dbench.roundTrips}, {@code -Dbench.clients}, {@code -Dbench.kills} change the sizes.
 */
public final class ClusterBenchmark {

    private static final int RUNS = Integer.getInteger("bench.runs", 5);
    private static final int ROUND_TRIPS = Integer.getInteger("bench.roundTrips", 2_000);
    private static final int CLIENTS = Integer.getInteger("bench.clients", 50);
    private static final int KILLS = Integer.getInteger("bench.kills", 10);
    private static final long CONCURRENT_MILLIS = Long.getLong("bench.concurrentMillis", 3_000);

    private ClusterBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        boolean latencyOnly = Arrays.asList(args).contains("latency");
        if (!CpuPlacement.isConfined()) {
            System.out.printf("cluster benchmark: %d runs, %d round trips per run, %d concurrent clients, %d crashes;"
                    + " %s, %d cores%n", RUNS, ROUND_TRIPS, CLIENTS, KILLS, System.getProperty("java.vm.version"),
                    Runtime.getRuntime().availableProcessors());
            if (!latencyOnly) {
                CpuPlacement.runConfined(ClusterBenchmark.class, "latency");
            }
        }
        try (LocalCluster cluster = LocalCluster.start(3); TcpEcho echo = new TcpEcho(16, 16);
             EmbeddedSpace embedded = EmbeddedSpace.open(); EmbeddedSpace served = EmbeddedSpace.open();
             Servers single = Servers.inFrontOf(List.of(served));
             Servers clustered = Servers.inFrontOf(List.of(cluster.member(0).openSpace("bench"),
                     cluster.member(1).openSpace("bench"), cluster.member(2).openSpace("bench")))) {
            ClusterSpace onFirst = cluster.member(0).openSpace("bench");
            ClusterSpace onSecond = cluster.member(1).openSpace("bench");
            RemoteSpace singleCaller = single.client(0);
            RemoteSpace singleProvider = single.client(0);
            RemoteSpace clusterCaller = clustered.client(0);
            RemoteSpace clusterProvider = clustered.client(1);
            System.out.printf("%nModule-call cycle, %s:%n", CpuPlacement.describe());
            warmUp(echo, List.of(embedded, onFirst, singleCaller, clusterCaller),
                    List.of(embedded, onSecond, singleProvider, clusterProvider), onFirst);
            List<Row> rows = new ArrayList<>();
            rows.add(measure("raw TCP loopback round trip (16-byte echo)", echo, () -> tcpRoundTrips(echo)));
            rows.add(measure("1 space server over HTTP, caller and provider remote", echo,
                    () -> moduleCalls(singleCaller, singleProvider)));
            rows.add(measure("3-member cluster over HTTP, servers of different members", echo,
                    () -> moduleCalls(clusterCaller, clusterProvider)));
            rows.add(measure("embedded space, caller and provider in one process", echo,
                    () -> moduleCalls(embedded, embedded)));
            rows.add(measure("3-member cluster in-process, caller and provider on different members", echo,
                    () -> moduleCalls(onFirst, onSecond)));
            rows.add(measure("3-member cluster in-process, write+take cycle on one member", echo,
                    () -> writeTakeCycles(onFirst)));
            print(rows);
            if (!latencyOnly) {
                System.out.printf("%n%d concurrent clients, write+take cycles on their own containers, %d ms per"
                        + " run, threads placed by the OS:%n", CLIENTS, CONCURRENT_MILLIS);
                concurrentClients("1 space server over HTTP", single.clients(CLIENTS));
                concurrentClients("3-member cluster over HTTP, clients spread over its servers",
                        clustered.clients(CLIENTS));
                concurrentClients("embedded space", List.of(embedded));
                List<Capi> handles = new ArrayList<>();
                for (ClusterMember member : cluster.members) {
                    handles.add(member.openSpace("bench"));
                }
                concurrentClients("3-member cluster in-process, clients spread over the members", handles);
                failover(cluster);
            }
        }
    }

    // ---- scenarios: each returns the latency samples of one run, in nanoseconds ----

    private static long[] tcpRoundTrips(TcpEcho echo) throws IOException {
        long[] samples = new long[ROUND_TRIPS * 4];
        for (int i = 0; i < samples.length; i++) {
            long start = System.nanoTime();
            echo.roundTrip();
            samples[i] = System.nanoTime() - start;
        }
        return samples;
    }

    private static long[] writeTakeCycles(Capi space) {
        ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
        long[] samples = new long[ROUND_TRIPS];
        for (int i = 0; i < samples.length; i++) {
            long start = System.nanoTime();
            space.write(queue, Timeout.TRY_ONCE, Entry.of(i));
            space.take(queue, Timeout.TRY_ONCE);
            samples[i] = System.nanoTime() - start;
        }
        space.destroyContainer(queue);
        return samples;
    }

    /** The cycle of a module call as the XVSM proxies make it: write-then-take against shift-then-take. */
    private static long[] moduleCalls(Capi caller, Capi provider) throws Exception {
        ModulePair pair = ModulePair.start(caller, provider);
        long[] samples = new long[ROUND_TRIPS];
        try {
            for (int i = 0; i < samples.length; i++) {
                long start = System.nanoTime();
                pair.call(i);
                samples[i] = System.nanoTime() - start;
            }
        } finally {
            pair.stop();
        }
        return samples;
    }

    /** A provider thread answering {@code <host, i>} with {@code <i + 1>} under the host's key. */
    private static final class ModulePair {
        final Capi caller;
        final Capi provider;
        final ContainerRef requests;
        final ContainerRef answers;
        final Thread module;

        private ModulePair(Capi caller, Capi provider) {
            this.caller = caller;
            this.provider = provider;
            requests = caller.createContainer(ContainerSpec.of(Order.FIFO));
            answers = caller.createContainer(ContainerSpec.of(Order.LIFO).withKeyView());
            module = new Thread(this::serve, "bench-module");
        }

        static ModulePair start(Capi caller, Capi provider) {
            ModulePair pair = new ModulePair(caller, provider);
            pair.module.start();
            return pair;
        }

        private void serve() {
            try {
                Tuple request = (Tuple) provider.take(requests, Timeout.INFINITE).get(0);
                while (request.arity() != 0) {
                    List<Item> answer = List.of(Item.keyed(request.stringAt(0), Tuple.of(request.longAt(1) + 1)));
                    request = (Tuple) provider.shiftThenTake(answers, answer, requests, Timeout.INFINITE).get(0);
                }
            } catch (SpaceException e) {
                // the provider's member crashed, or the benchmark ended
            }
        }

        void call(long i) {
            Tuple answer = (Tuple) caller.writeThenTake(requests, List.of(Item.of(Tuple.of("A", i))), answers,
                    Timeout.ofMillis(10_000), Selector.key("A")).get(0);
            if (answer.longAt(0) != i + 1) {
                throw new IllegalStateException("wrong answer " + answer + " for " + i);
            }
        }

        void stop() throws InterruptedException {
            try {
                caller.write(requests, Timeout.TRY_ONCE, Tuple.of());
            } catch (SpaceException e) {
                module.interrupt();
            }
            module.join(10_000);
        }
    }

    private static void concurrentClients(String name, List<Capi> spaces) throws Exception {
        List<ContainerRef> queues = new ArrayList<>();
        for (int c = 0; c < CLIENTS; c++) {
            queues.add(spaces.get(c % spaces.size()).createContainer(ContainerSpec.of(Order.FIFO)));
        }
        List<Double> throughputs = new ArrayList<>();
        List<Double> p50s = new ArrayList<>();
        List<Double> p99s = new ArrayList<>();
        for (int run = -1; run < 3; run++) { // run -1 warms up
            long[][] perClient = new long[CLIENTS][];
            CyclicBarrier start = new CyclicBarrier(CLIENTS + 1);
            CountDownLatch done = new CountDownLatch(CLIENTS);
            long[] stopAt = new long[1];
            for (int c = 0; c < CLIENTS; c++) {
                int index = c;
                Capi space = spaces.get(c % spaces.size());
                Thread worker = new Thread(() -> {
                    long[] samples = new long[1 << 16];
                    int count = 0;
                    try {
                        start.await();
                        while (System.nanoTime() < stopAt[0] && count < samples.length) {
                            long begin = System.nanoTime();
                            space.write(queues.get(index), Timeout.TRY_ONCE, Entry.of(count));
                            space.take(queues.get(index), Timeout.TRY_ONCE);
                            samples[count++] = System.nanoTime() - begin;
                        }
                    } catch (Exception e) {
                        e.printStackTrace();
                    } finally {
                        perClient[index] = Arrays.copyOf(samples, count);
                        done.countDown();
                    }
                }, "bench-client-" + c);
                worker.start();
            }
            stopAt[0] = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(CONCURRENT_MILLIS);
            long begin = System.nanoTime();
            start.await();
            done.await();
            double seconds = (System.nanoTime() - begin) / 1e9;
            long[] all = Arrays.stream(perClient).flatMapToLong(Arrays::stream).toArray();
            Arrays.sort(all);
            if (run >= 0) {
                throughputs.add(all.length * 2 / seconds);
                p50s.add(percentile(all, 0.50) / 1e3);
                p99s.add(percentile(all, 0.99) / 1e3);
            }
        }
        System.out.printf("  %-52s %,10.0f operations/s, cycle p50 %6.0f us, p99 %7.0f us (median of 3 runs)%n",
                name, median(throughputs), median(p50s), median(p99s));
    }

    /**
     * Crashes, {@link #KILLS} times, the member that owns the caller's request or answer container (never the
     * caller's or the provider's own member), and measures the longest pause between two completed calls.
     */
    private static void failover(LocalCluster cluster) throws Exception {
        System.out.printf("%nFailover: a caller makes module calls while the member owning one of its containers"
                + " crashes; longest pause between two completed calls, %d crashes:%n", KILLS);
        ClusterSpace caller = cluster.member(0).openSpace("failover");
        ClusterSpace provider = cluster.member(1).openSpace("failover");
        List<Double> pauses = new ArrayList<>();
        long errors = 0;
        for (int kill = 0; kill < KILLS; kill++) {
            ClusterMember victim = cluster.member(2);
            ModulePair pair = ModulePair.start(caller, provider);
            while (!victim.owns(pair.requests) && !victim.owns(pair.answers)) {
                pair.stop();
                pair = ModulePair.start(caller, provider);
            }
            AtomicBoolean running = new AtomicBoolean(true);
            AtomicLong longestPause = new AtomicLong();
            AtomicLong failures = new AtomicLong();
            ModulePair calls = pair;
            Thread loop = new Thread(() -> {
                long last = System.nanoTime();
                for (long i = 0; running.get(); i++) {
                    try {
                        calls.call(i);
                    } catch (SpaceException | IllegalStateException e) {
                        failures.incrementAndGet();
                        continue;
                    }
                    long now = System.nanoTime();
                    longestPause.accumulateAndGet(now - last, Math::max);
                    last = now;
                }
            }, "bench-caller");
            loop.start();
            Thread.sleep(1_000);
            longestPause.set(0); // only the pause around the crash counts
            victim.crash();
            cluster.members.remove(victim);
            Thread.sleep(3_000);
            running.set(false);
            loop.join(30_000);
            pair.stop();
            pauses.add(longestPause.get() / 1e6);
            errors += failures.get();
            System.out.printf("  crash %2d: longest pause %6.0f ms, failed calls %d%n", kill + 1,
                    longestPause.get() / 1e6, failures.get());
            cluster.addMember();
            cluster.awaitSize(3);
        }
        pauses.sort(Double::compare);
        System.out.printf("  pause over %d crashes: min %.0f ms, median %.0f ms, p90 %.0f ms, max %.0f ms; failed"
                + " calls %d%n", pauses.size(), pauses.get(0), pauses.get(pauses.size() / 2),
                pauses.get((int) Math.min(pauses.size() - 1, Math.floor(pauses.size() * 0.9))),
                pauses.get(pauses.size() - 1), errors);
    }

    // ---- measuring ----

    @FunctionalInterface
    private interface Scenario {
        long[] run() throws Exception;
    }

    private record Row(String name, double p50, double p99, double ratio) {
    }

    private static void warmUp(TcpEcho echo, List<Capi> callers, List<Capi> providers, Capi cycles)
            throws Exception {
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(Long.getLong("bench.warmupSeconds", 8));
        while (System.nanoTime() < until) {
            tcpRoundTrips(echo);
            for (int i = 0; i < callers.size(); i++) {
                moduleCalls(callers.get(i), providers.get(i));
            }
            writeTakeCycles(cycles);
        }
    }

    /**
     * Space servers on loopback in front of the given spaces, and remote clients of them, as programs on other
     * computers would have: one client each, closed with the servers.
     */
    private static final class Servers implements AutoCloseable {
        private final List<SpaceServer> servers = new ArrayList<>();
        private final List<RemoteSpace> clients = new ArrayList<>();

        static Servers inFrontOf(List<? extends SpaceEngine> spaces) {
            Servers started = new Servers();
            for (SpaceEngine space : spaces) {
                started.servers.add(SpaceServer.start(space, SpaceServer.Options.defaults().port(0)
                        .stopGraceMillis(100)));
            }
            return started;
        }

        /** A new client of server {@code index}. */
        RemoteSpace client(int index) {
            RemoteSpace client = RemoteSpace.open(servers.get(index).uri(), RemoteSpace.Options.defaults());
            clients.add(client);
            return client;
        }

        /** {@code count} new clients, spread over the servers in turn. */
        List<Capi> clients(int count) {
            List<Capi> made = new ArrayList<>();
            for (int c = 0; c < count; c++) {
                made.add(client(c % servers.size()));
            }
            return made;
        }

        @Override
        public void close() {
            clients.forEach(RemoteSpace::close);
            servers.forEach(SpaceServer::stop);
        }
    }

    private static Row measure(String name, TcpEcho echo, Scenario scenario) throws Exception {
        List<Double> p50s = new ArrayList<>();
        List<Double> p99s = new ArrayList<>();
        List<Double> ratios = new ArrayList<>();
        for (int run = 0; run < RUNS; run++) {
            long[] tcp = tcpRoundTrips(echo);
            Arrays.sort(tcp);
            long[] samples = scenario.run();
            Arrays.sort(samples);
            double p50 = percentile(samples, 0.50) / 1e3;
            p50s.add(p50);
            p99s.add(percentile(samples, 0.99) / 1e3);
            ratios.add(p50 / (percentile(tcp, 0.50) / 1e3));
        }
        return new Row(name, median(p50s), median(p99s), median(ratios));
    }

    private static void print(List<Row> rows) {
        System.out.printf("%n%-62s %8s %8s %7s%n", "scenario", "p50 us", "p99 us", "x TCP");
        for (Row row : rows) {
            System.out.printf("%-62s %8.1f %8.1f %7.1f%n", row.name(), row.p50(), row.p99(), row.ratio());
        }
    }

    private static double percentile(long[] sorted, double fraction) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        return sorted[Math.min(sorted.length - 1, (int) Math.floor(fraction * sorted.length))];
    }

    private static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        sorted.sort(Double::compare);
        return sorted.get(sorted.size() / 2);
    }
}
