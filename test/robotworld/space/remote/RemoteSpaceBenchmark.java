package robotworld.space.remote;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.Item;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Subscription;
import robotworld.space.Timeout;
import robotworld.space.Tuple;
import robotworld.space.server.SpaceServer;
import redis.clients.jedis.Jedis;
import robotworld.testsupport.CpuPlacement;
import robotworld.testsupport.JitWarmUp;
import robotworld.testsupport.RedisPeer;
import robotworld.testsupport.SpaceServerProcess;
import robotworld.testsupport.TcpEcho;

/**
 * Remote space latencies next to a raw TCP loopback round trip measured in the same run: a write+take cycle, the
 * request/answer cycle of a remote module call, notification latency, one trivial request with this client and
 * with {@code java.net.http.HttpClient}, and 50 concurrent clients. Each figure is the median over several
 * timed runs (after warm-up) of that run's percentile; each run is paired with a TCP batch measured just before
 * it, and the "x TCP" column is the median of those per-run ratios. The latency part runs twice: in a child JVM
 * with every thread on one CPU, and with threads placed by the OS (see {@link CpuPlacement} for why). Run with
 * {@code ./antw bench-remote}; argument {@code latency} skips the concurrent clients.
 */
public final class RemoteSpaceBenchmark {

    private static final int RUNS = Integer.getInteger("bench.runs", 5);
    private static final int ROUND_TRIPS = Integer.getInteger("bench.roundTrips", 3_000);
    private static final int CLIENTS = Integer.getInteger("bench.clients", 50);
    private static final double TARGET_RATIO = 8.0;
    private static final long CONCURRENT_MILLIS = Long.getLong("bench.concurrentMillis", 3_000);
    private static final int PAIRS = Integer.getInteger("bench.pairs", 50);
    private static final long PAIR_MILLIS = Long.getLong("bench.pairMillis", 5_000);

    /** Clients that send operations as HTTP requests, as before frames: the step measured beside them. */
    private static final RemoteSpace.Options HTTP = RemoteSpace.Options.defaults().frames(false);
    /** Clients that send frames with JSON bodies, as before the binary form: the step measured beside them. */
    private static final RemoteSpace.Options JSON_BODIES = RemoteSpace.Options.defaults().binary(false);

    private RemoteSpaceBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        boolean latencyOnly = Arrays.asList(args).contains("latency");
        if (Boolean.getBoolean("bench.pairsOnly")) { // -Dbench.pairsOnly=true: only the 50 pairs against Redis
            try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0));
                 RedisPeer redis = RedisPeer.start()) {
                pairs(server.uri(), redis);
            }
            return;
        }
        if (!CpuPlacement.isConfined()) {
            System.out.printf("remote space benchmark: %d runs, %d round trips per run, %d concurrent clients; %s,"
                    + " %d cores%n", RUNS, ROUND_TRIPS, CLIENTS, System.getProperty("java.vm.version"),
                    Runtime.getRuntime().availableProcessors());
            if (!latencyOnly) {
                CpuPlacement.runConfined(RemoteSpaceBenchmark.class, "latency");
            }
        }
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0));
             TcpEcho echo = new TcpEcho(16, 16);
             RedisPeer redis = RedisPeer.start()) {
            URI uri = server.uri();
            System.out.printf("%nLatency, %s:%n", CpuPlacement.describe());
            List<Row> rows = new ArrayList<>();
            warmUp(uri, echo, redis);
            long compiledBefore = JitWarmUp.compileMillis();
            long measuredFrom = System.nanoTime();
            Row tcp = measure("raw TCP loopback round trip (16-byte echo)", echo, () -> tcpRoundTrips(echo));
            rows.add(tcp);
            rows.add(measure("remote write+take cycle (2 requests)", echo, () -> writeTakeCycles(uri)));
            rows.add(measure("request/answer cycle, one request per operation (A 2, B 2)", echo,
                    () -> requestAnswerCycles(uri, false)));
            Row call = measure("request/answer cycle of a remote module call (A 1, B 1)", echo,
                    () -> requestAnswerCycles(uri, true));
            rows.add(call);
            rows.add(measure("the same, bodies as JSON instead of binary", echo,
                    () -> requestAnswerCycles(uri, true, JSON_BODIES)));
            rows.add(measure("the same, operations as HTTP requests instead of frames", echo,
                    () -> requestAnswerCycles(uri, true, HTTP)));
            rows.add(measure("module-call cycle, B waiting without a thread (shiftThenTakeLater)", echo,
                    () -> threadlessModuleCycles(uri)));
            Row redisCall = redis == null ? null : measure("Redis request/answer cycle (A: RPUSH+BLPOP; B: BLPOP, RPUSH)",
                    echo, () -> redisCycles(redis));
            if (redisCall != null) {
                rows.add(redisCall);
            }
            Row notification = measure("notification latency (write call to listener)", echo,
                    () -> notificationLatencies(uri));
            rows.add(notification);
            rows.add(measure("one trivial request (describe), this client", echo, () -> describeCalls(uri)));
            rows.add(measure("one trivial request (describe), java.net.http.HttpClient", echo,
                    () -> jdkHttpCalls(uri)));
            print(rows);
            System.out.printf("JIT compile time while these rows were measured: %d ms in %.0f s%n",
                    JitWarmUp.compileMillis() - compiledBefore, (System.nanoTime() - measuredFrom) / 1e9);
            System.out.printf("%n%s: request/answer p50 = %.1f x the TCP round trip measured just before it, median"
                    + " of %d runs (target <= %.0f: %s); notification p50 = %.0f us (target <= 300: %s)%n",
                    CpuPlacement.describe(), call.ratio(), RUNS, TARGET_RATIO,
                    call.ratio() <= TARGET_RATIO ? "met" : "NOT met", notification.p50(),
                    notification.p50() <= 300 ? "met" : "NOT met");
            if (redisCall != null) {
                System.out.printf("%s: module-call cycle p50 = %.2f x the Redis cycle measured in the same run"
                        + " (target <= 1: %s), %.1f x the TCP round trip (target <= 5: %s)%n", CpuPlacement.describe(),
                        call.p50() / redisCall.p50(), call.p50() <= redisCall.p50() ? "met" : "NOT met", call.ratio(),
                        call.ratio() <= 5 ? "met" : "NOT met");
            }
            if (!latencyOnly) {
                concurrentClients(uri);
                pairs(uri, redis);
            }
        }
    }

    /** The 50 pairs against Redis, with the space server in its own process unless told otherwise. */
    private static void pairs(URI uri, RedisPeer redis) throws Exception {
        if (Boolean.parseBoolean(System.getProperty("bench.pairsInProcess", "false"))) {
            System.out.printf("%nspace server for the pairs: in this JVM (-Dbench.pairsInProcess=true)%n");
            concurrentPairs(uri, null, redis, 1);
        } else {
            // as Redis is: its own process, so its heap and collector are not the 100 clients' ones
            List<String> jvm = new ArrayList<>(List.of("-Xmx1g"));
            String extra = System.getProperty("bench.pairsServerJvmArgs", ""); // e.g. a flight recording
            if (!extra.isBlank()) {
                jvm.addAll(List.of(extra.trim().split("\\s+")));
            }
            String compare = System.getProperty("bench.pairsCompare", "");
            if (!compare.isBlank()) {
                List<String> other = new ArrayList<>(jvm);
                other.addAll(List.of(compare.trim().split("\\s+")));
                try (SpaceServerProcess a = SpaceServerProcess.start(jvm);
                     SpaceServerProcess b = SpaceServerProcess.start(other)) {
                    comparePairs(a, b, compare, redis);
                }
                return;
            }
            try (SpaceServerProcess own = SpaceServerProcess.start(jvm)) {
                System.out.printf("%nspace server for the pairs: its own process (rwe space, -Xmx1g), as"
                        + " Redis is; three warm-up runs, since its JIT starts cold%n");
                concurrentPairs(own.uri(), ProcessHandle.of(own.pid()).orElseThrow(), redis, 3);
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

    private static long[] writeTakeCycles(URI uri) {
        try (RemoteSpace space = RemoteSpace.open(uri)) {
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
    }

    /**
     * Client A writes {@code <A, i>} to a FIFO REQUEST container; client B, blocked in a take, receives it and
     * shifts the answer under A's key into a LIFO+KEY ANSWER container; A, blocked in a take of its key, receives it.
     * With {@code composite}, both sides do what the XVSM proxies do: A sends its write and its take in one request
     * ({@code writeThenTake}), B its shift and its next take ({@code shiftThenTake}). Otherwise each operation is a
     * request of its own, each take sent once the write or shift before it is answered.
     */
    private static long[] requestAnswerCycles(URI uri, boolean composite) throws Exception {
        return requestAnswerCycles(uri, composite, RemoteSpace.Options.defaults());
    }

    /** As above, with clients of {@code options} (operations as HTTP requests instead of frames, say). */
    private static long[] requestAnswerCycles(URI uri, boolean composite, RemoteSpace.Options options)
            throws Exception {
        try (RemoteSpace a = RemoteSpace.open(uri, options); RemoteSpace b = RemoteSpace.open(uri, options)) {
            String suffix = Long.toString(System.nanoTime());
            ContainerRef requests = a.createContainer(ContainerSpec.of(Order.FIFO).named("REQUEST" + suffix));
            ContainerRef answers = a.createContainer(ContainerSpec.of(Order.LIFO).withKeyView().named("ANSWER" + suffix));
            Thread module = new Thread(() -> {
                Tuple request = (Tuple) b.take(requests, Timeout.INFINITE).get(0);
                while (request.arity() != 0) {
                    List<Item> answer = List.of(Item.keyed(request.stringAt(0), Tuple.of(request.longAt(1) + 1)));
                    if (composite) {
                        request = (Tuple) b.shiftThenTake(answers, answer, requests, Timeout.INFINITE).get(0);
                    } else {
                        b.shift(answers, Timeout.TRY_ONCE, answer);
                        request = (Tuple) b.take(requests, Timeout.INFINITE).get(0);
                    }
                }
            }, "bench-module");
            module.start();
            long[] samples = new long[ROUND_TRIPS];
            for (int i = 0; i < samples.length; i++) {
                long start = System.nanoTime();
                Tuple answer;
                if (composite) {
                    answer = (Tuple) a.writeThenTake(requests, List.of(Item.of(Tuple.of("A", i))), answers,
                            Timeout.ofMillis(5_000), Selector.key("A")).get(0);
                } else {
                    a.write(requests, Timeout.TRY_ONCE, Tuple.of("A", i));
                    answer = (Tuple) a.take(answers, Timeout.ofMillis(5_000), Selector.key("A")).get(0);
                }
                samples[i] = System.nanoTime() - start;
                if (answer.longAt(0) != i + 1) {
                    throw new IllegalStateException("wrong answer " + answer + " for " + i);
                }
            }
            a.write(requests, Timeout.TRY_ONCE, Tuple.of());
            module.join();
            a.destroyContainer(requests);
            a.destroyContainer(answers);
            return samples;
        }
    }

    /**
     * The module-call cycle as a runtime's Local side serves it: B waits without a thread
     * ({@link RemoteSpace#shiftThenTakeLater}); the request goes from B's I/O thread to a worker thread, which
     * answers it and starts the next wait.
     */
    private static long[] threadlessModuleCycles(URI uri) throws Exception {
        java.util.concurrent.ExecutorService worker = java.util.concurrent.Executors.newSingleThreadExecutor();
        try (RemoteSpace a = RemoteSpace.open(uri); RemoteSpace b = RemoteSpace.open(uri)) {
            String suffix = Long.toString(System.nanoTime());
            ContainerRef requests = a.createContainer(ContainerSpec.of(Order.FIFO).named("REQUEST" + suffix));
            ContainerRef answers = a.createContainer(ContainerSpec.of(Order.LIFO).withKeyView().named("ANSWER" + suffix));
            CountDownLatch over = new CountDownLatch(1);
            robotworld.space.SpaceEngine.Completion<List<Entry>> serve = new robotworld.space.SpaceEngine.Completion<>() {
                @Override
                public void completed(List<Entry> entries) {
                    worker.execute(() -> {
                        Tuple request = (Tuple) entries.get(0);
                        if (request.arity() == 0) {
                            over.countDown();
                            return;
                        }
                        b.shiftThenTakeLater(answers, List.of(Item.keyed(request.stringAt(0),
                                Tuple.of(request.longAt(1) + 1))), requests, Timeout.INFINITE, new Selector[0], this);
                    });
                }

                @Override
                public void failed(robotworld.space.SpaceException failure) {
                    failure.printStackTrace();
                    over.countDown();
                }
            };
            b.takeLater(requests, Timeout.INFINITE, new Selector[0], serve);
            long[] samples = new long[ROUND_TRIPS];
            for (int i = 0; i < samples.length; i++) {
                long start = System.nanoTime();
                Tuple answer = (Tuple) a.writeThenTake(requests, List.of(Item.of(Tuple.of("A", i))), answers,
                        Timeout.ofMillis(5_000), Selector.key("A")).get(0);
                samples[i] = System.nanoTime() - start;
                if (answer.longAt(0) != i + 1) {
                    throw new IllegalStateException("wrong answer " + answer + " for " + i);
                }
            }
            a.write(requests, Timeout.TRY_ONCE, Tuple.of());
            over.await(5, TimeUnit.SECONDS);
            a.destroyContainer(requests);
            a.destroyContainer(answers);
            return samples;
        } finally {
            worker.shutdownNow();
        }
    }

    /**
     * The same cycle with Redis and Jedis, as an engineer would write it there: A pushes its request onto a list
     * and blocks popping its own answer list; B blocks popping the request list and pushes the answer onto A's.
     */
    private static long[] redisCycles(RedisPeer redis) throws Exception {
        String suffix = Long.toString(System.nanoTime());
        String requests = "req" + suffix;
        String answers = "ans" + suffix + ":A";
        try (Jedis a = redis.connect(); Jedis b = redis.connect()) {
            Thread module = new Thread(() -> {
                while (true) {
                    String request = b.blpop(0, requests).get(1);
                    if (request.isEmpty()) {
                        return;
                    }
                    int colon = request.indexOf(':');
                    b.rpush("ans" + suffix + ":" + request.substring(0, colon),
                            Long.toString(Long.parseLong(request.substring(colon + 1)) + 1));
                }
            }, "bench-redis-module");
            module.start();
            long[] samples = new long[ROUND_TRIPS];
            for (int i = 0; i < samples.length; i++) {
                long start = System.nanoTime();
                a.rpush(requests, "A:" + i);
                String answer = a.blpop(5, answers).get(1);
                samples[i] = System.nanoTime() - start;
                if (Long.parseLong(answer) != i + 1) {
                    throw new IllegalStateException("wrong Redis answer " + answer + " for " + i);
                }
            }
            a.rpush(requests, "");
            module.join();
            return samples;
        }
    }

    private static long[] notificationLatencies(URI uri) throws Exception {
        try (RemoteSpace writer = RemoteSpace.open(uri); RemoteSpace observer = RemoteSpace.open(uri)) {
            ContainerRef observed = writer.createContainer(ContainerSpec.of(Order.FIFO).bounded(1));
            long[] samples = new long[ROUND_TRIPS];
            AtomicLong received = new AtomicLong(-1);
            Object signal = new Object();
            Subscription subscription = observer.subscribe(observed, EnumSet.of(Operation.SHIFT),
                    NotificationMode.INFINITE, Timeout.INFINITE, notification -> {
                        long sentAt = ((IntEntry) notification.entries().get(0)).value();
                        synchronized (signal) {
                            received.set(System.nanoTime() - sentAt);
                            signal.notifyAll();
                        }
                    });
            for (int i = 0; i < samples.length; i++) {
                received.set(-1);
                writer.shift(observed, Timeout.TRY_ONCE, Entry.of(System.nanoTime()));
                synchronized (signal) {
                    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
                    while (received.get() < 0) {
                        if (System.nanoTime() > deadline) {
                            throw new IllegalStateException("notification " + i + " never came");
                        }
                        signal.wait(100);
                    }
                }
                samples[i] = received.get();
            }
            subscription.cancel();
            return samples;
        }
    }

    private static long[] describeCalls(URI uri) {
        try (RemoteSpace space = RemoteSpace.open(uri)) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
            long[] samples = new long[ROUND_TRIPS];
            for (int i = 0; i < samples.length; i++) {
                long start = System.nanoTime();
                space.describeContainer(ref);
                samples[i] = System.nanoTime() - start;
            }
            return samples;
        }
    }

    private static long[] jdkHttpCalls(URI uri) throws Exception {
        try (RemoteSpace space = RemoteSpace.open(uri)) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
            HttpClient client = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1).build();
            HttpRequest request = HttpRequest.newBuilder(URI.create(uri + "/describe"))
                    .header("Content-Type", "application/json")
                    .POST(HttpRequest.BodyPublishers.ofString("{\"container\":{\"cref\":\"" + ref.id()
                            + "\",\"space\":\"" + ref.space() + "\"}}"))
                    .build();
            long[] samples = new long[ROUND_TRIPS];
            for (int i = 0; i < samples.length; i++) {
                long start = System.nanoTime();
                HttpResponse<byte[]> response = client.send(request, HttpResponse.BodyHandlers.ofByteArray());
                samples[i] = System.nanoTime() - start;
                if (response.statusCode() != 200) {
                    throw new IllegalStateException("HTTP " + response.statusCode());
                }
            }
            return samples;
        }
    }

    /** {@link #CLIENTS} clients, each with its own connection and container, doing write+take cycles at once. */
    private static void concurrentClients(URI uri) throws Exception {
        System.out.printf("%n%d concurrent clients, write+take cycles on their own containers, %d ms per run:%n",
                CLIENTS, CONCURRENT_MILLIS);
        List<RemoteSpace> clients = new ArrayList<>();
        List<ContainerRef> queues = new ArrayList<>();
        for (int c = 0; c < CLIENTS; c++) {
            RemoteSpace client = RemoteSpace.open(uri);
            clients.add(client);
            queues.add(client.createContainer(ContainerSpec.of(Order.FIFO)));
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
                Thread worker = new Thread(() -> {
                    long[] samples = new long[1 << 16];
                    int count = 0;
                    try {
                        start.await();
                        while (System.nanoTime() < stopAt[0] && count < samples.length) {
                            long begin = System.nanoTime();
                            clients.get(index).write(queues.get(index), Timeout.TRY_ONCE, Entry.of(count));
                            clients.get(index).take(queues.get(index), Timeout.TRY_ONCE);
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
                System.out.printf("  run %d: %,.0f operations/s (%,d cycles), cycle p50 %.0f us, p99 %.0f us%n", run + 1,
                        all.length * 2 / seconds, all.length, percentile(all, 0.50) / 1e3, percentile(all, 0.99) / 1e3);
            }
        }
        System.out.printf("  median: %,.0f operations/s, cycle p50 %.0f us, p99 %.0f us%n", median(throughputs),
                median(p50s), median(p99s));
        clients.forEach(Capi::close);
    }

    /**
     * {@link #PAIRS} request/answer pairs at once, each a caller and a module with containers (or Redis lists) of
     * their own, doing the module-call cycle as fast as answers come; ours and Redis alternately, 3 runs each.
     */
    /**
     * The pairs against two servers in processes of their own, the second with the JVM options {@code compare}
     * ({@code -Dbench.pairsCompare=...}, e.g. a system property that switches a trial change on), and Redis, in
     * turn: an A/B trial measured in one run, on the same machine state.
     */
    private static void comparePairs(SpaceServerProcess a, SpaceServerProcess b, String compare, RedisPeer redis)
            throws Exception {
        System.out.printf("%n%d concurrent request/answer pairs, %d ms per run: server A as configured, server B with"
                + " %s, and Redis, in turn (three warm-up rounds, then 5):%n", PAIRS, PAIR_MILLIS, compare);
        ProcessHandle processA = ProcessHandle.of(a.pid()).orElseThrow();
        ProcessHandle processB = ProcessHandle.of(b.pid()).orElseThrow();
        List<Way> ways = new ArrayList<>(List.of(
                new Way("A", () -> pairsRun(a.uri(), processA, null, RemoteSpace.Options.defaults())),
                new Way("B", () -> pairsRun(b.uri(), processB, null, RemoteSpace.Options.defaults()))));
        if (redis != null) {
            ways.add(new Way("Redis", () -> pairsRun(a.uri(), redisProcess(redis), redis, null)));
        }
        List<PairsRun> medians = inTurn(ways, 3, 5);
        for (int i = 0; i < ways.size(); i++) {
            System.out.printf("  median %s: %s%n", ways.get(i).label(), medians.get(i));
        }
    }

    private static void concurrentPairs(URI uri, ProcessHandle server, RedisPeer redis, int warmUpRuns)
            throws Exception {
        System.out.printf("%n%d concurrent request/answer pairs (module-call cycles), %d ms per run, ours (frames,"
                + " then frames with JSON bodies, then HTTP) and Redis alternately:%n", PAIRS, PAIR_MILLIS);
        List<Way> ways = new ArrayList<>(List.of(
                new Way("space", () -> pairsRun(uri, server, null, RemoteSpace.Options.defaults())),
                new Way("over HTTP", () -> pairsRun(uri, server, null, HTTP)),
                new Way("JSON bodies", () -> pairsRun(uri, server, null, JSON_BODIES))));
        if (redis != null) {
            ways.add(new Way("Redis", () -> pairsRun(uri, redisProcess(redis), redis, null)));
        }
        List<PairsRun> medians = inTurn(ways, warmUpRuns, 3);
        PairsRun space = medians.get(0);
        System.out.printf("  median: space %s%n", space);
        PairsRun http = medians.get(1);
        System.out.printf("  median: space over HTTP %s (frames: %.2f x its calls/s)%n", http,
                space.callsPerSecond / http.callsPerSecond);
        PairsRun json = medians.get(2);
        System.out.printf("  median: space with JSON bodies %s (binary: %.2f x its calls/s)%n", json,
                space.callsPerSecond / json.callsPerSecond);
        if (redis != null) {
            PairsRun r = medians.get(3);
            System.out.printf("  median: Redis %s%n", r);
            System.out.printf("  %d pairs: space %.2f x Redis calls/s (target >= 1: %s), p99 %.2f x Redis p99 (target"
                    + " <= 1: %s)%n", PAIRS, space.callsPerSecond / r.callsPerSecond,
                    space.callsPerSecond >= r.callsPerSecond ? "met" : "NOT met", space.p99Micros / r.p99Micros,
                    space.p99Micros <= r.p99Micros ? "met" : "NOT met");
        }
    }

    /** One way of running the pairs (a server, a protocol, or Redis), named in the output. */
    private record Way(String label, Callable<PairsRun> run) {
    }

    /**
     * Runs each way in turn, round after round, so that all see the same machine: {@code warmUps} rounds not
     * counted, then {@code rounds} printed. Returns each way's medians, in the order of {@code ways}.
     */
    private static List<PairsRun> inTurn(List<Way> ways, int warmUps, int rounds) throws Exception {
        List<List<PairsRun>> runs = new ArrayList<>();
        ways.forEach(way -> runs.add(new ArrayList<>()));
        for (int round = -warmUps; round < rounds; round++) {
            List<PairsRun> these = new ArrayList<>();
            for (Way way : ways) {
                these.add(way.run().call());
            }
            if (round >= 0) {
                System.out.printf("  run %d:%n", round + 1);
                for (int i = 0; i < ways.size(); i++) {
                    runs.get(i).add(these.get(i));
                    System.out.printf("    %s %s%n", ways.get(i).label(), these.get(i));
                }
            }
        }
        return runs.stream().map(PairsRun::medians).toList();
    }

    /** The redis-server process, for its CPU time. */
    private static ProcessHandle redisProcess(RedisPeer redis) {
        return ProcessHandle.of(redis.pid()).orElseThrow();
    }

    /** CPU time a process has used so far, in ns; -1 where the OS does not say. */
    private static long cpuNanos(ProcessHandle process) {
        return process.info().totalCpuDuration().map(java.time.Duration::toNanos).orElse(-1L);
    }

    /** CPU time this JVM has used so far, in ns (the clients; and the server too when it runs in here). */
    private static long ownCpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory
                .getOperatingSystemMXBean()).getProcessCpuTime();
    }

    /**
     * One run of {@link #PAIRS} pairs, with Redis when {@code redis} is given, else with space clients of
     * {@code options}; {@code server} is the server's process (for its CPU time), null if it runs in this JVM.
     */
    private static PairsRun pairsRun(URI uri, ProcessHandle server, RedisPeer redis, RemoteSpace.Options options)
            throws Exception {
        String suffix = Long.toString(System.nanoTime());
        List<AutoCloseable> resources = new ArrayList<>();
        long[][] perCaller = new long[PAIRS][];
        long[][] endedAt = new long[PAIRS][];
        CyclicBarrier start = new CyclicBarrier(PAIRS + 1);
        CountDownLatch done = new CountDownLatch(PAIRS);
        long[] stopAt = new long[1];
        List<Thread> modules = new ArrayList<>();
        try {
            for (int p = 0; p < PAIRS; p++) {
                int pair = p;
                Runnable caller;
                if (redis == null) {
                    RemoteSpace a = RemoteSpace.open(uri, options);
                    RemoteSpace b = RemoteSpace.open(uri, options);
                    resources.add(a);
                    resources.add(b);
                    ContainerRef requests = a.createContainer(ContainerSpec.of(Order.FIFO).named("REQ" + suffix + p));
                    ContainerRef answers = a.createContainer(ContainerSpec.of(Order.LIFO).withKeyView()
                            .named("ANS" + suffix + p));
                    modules.add(new Thread(() -> {
                        try {
                            Tuple request = (Tuple) b.take(requests, Timeout.INFINITE).get(0);
                            while (request.arity() != 0) {
                                request = (Tuple) b.shiftThenTake(answers, List.of(Item.keyed(request.stringAt(0),
                                        Tuple.of(request.longAt(1) + 1))), requests, Timeout.INFINITE).get(0);
                            }
                        } catch (RuntimeException closed) {
                            // the run is over
                        }
                    }, "bench-pair-module-" + p));
                    caller = () -> {
                        long[] samples = new long[1 << 16];
                        long[] ends = new long[1 << 16];
                        int count = 0;
                        while (System.nanoTime() < stopAt[0] && count < samples.length) {
                            long begin = System.nanoTime();
                            Tuple answer = (Tuple) a.writeThenTake(requests, List.of(Item.of(Tuple.of("A", count))),
                                    answers, Timeout.ofMillis(10_000), Selector.key("A")).get(0);
                            if (answer.longAt(0) != count + 1) {
                                throw new IllegalStateException("wrong answer " + answer);
                            }
                            long end = System.nanoTime();
                            ends[count] = end;
                            samples[count++] = end - begin;
                        }
                        a.write(requests, Timeout.TRY_ONCE, Tuple.of());
                        perCaller[pair] = Arrays.copyOf(samples, count);
                        endedAt[pair] = Arrays.copyOf(ends, count);
                    };
                } else {
                    Jedis a = redis.connect();
                    Jedis b = redis.connect();
                    resources.add(a);
                    resources.add(b);
                    String requests = "req" + suffix + ":" + p;
                    String answers = "ans" + suffix + ":" + p + ":A";
                    modules.add(new Thread(() -> {
                        while (true) {
                            String request = b.blpop(0, requests).get(1);
                            if (request.isEmpty()) {
                                return;
                            }
                            b.rpush(answers, Long.toString(Long.parseLong(request) + 1));
                        }
                    }, "bench-pair-redis-" + p));
                    caller = () -> {
                        long[] samples = new long[1 << 16];
                        long[] ends = new long[1 << 16];
                        int count = 0;
                        while (System.nanoTime() < stopAt[0] && count < samples.length) {
                            long begin = System.nanoTime();
                            a.rpush(requests, Integer.toString(count));
                            String answer = a.blpop(10, answers).get(1);
                            if (Long.parseLong(answer) != count + 1) {
                                throw new IllegalStateException("wrong Redis answer " + answer);
                            }
                            long end = System.nanoTime();
                            ends[count] = end;
                            samples[count++] = end - begin;
                        }
                        a.rpush(requests, "");
                        perCaller[pair] = Arrays.copyOf(samples, count);
                        endedAt[pair] = Arrays.copyOf(ends, count);
                    };
                }
                Runnable body = caller;
                Thread thread = new Thread(() -> {
                    try {
                        start.await();
                        body.run();
                    } catch (Exception e) {
                        e.printStackTrace();
                    } finally {
                        done.countDown();
                    }
                }, "bench-pair-caller-" + p);
                thread.start();
            }
            modules.forEach(Thread::start);
            stopAt[0] = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(PAIR_MILLIS);
            long begin = System.nanoTime();
            long serverCpu = server == null ? -1 : cpuNanos(server);
            long clientCpu = ownCpuNanos();
            start.await();
            done.await();
            double seconds = (System.nanoTime() - begin) / 1e9;
            serverCpu = server == null || serverCpu < 0 ? -1 : cpuNanos(server) - serverCpu;
            clientCpu = ownCpuNanos() - clientCpu;
            for (Thread module : modules) {
                module.join(5_000);
            }
            return PairsRun.of(perCaller, endedAt, begin, seconds, serverCpu, clientCpu);
        } finally {
            for (AutoCloseable resource : resources) {
                resource.close();
            }
        }
    }

    // ---- measuring ----

    @FunctionalInterface
    private interface Scenario {
        long[] run() throws Exception;
    }

    /** A scenario's median p50 and p99, the median of its per-run ratios to the TCP p50, and the per-run values. */
    private record Row(String name, double p50, double p99, double ratio, List<Double> runP50s, List<Double> tcpP50s) {
    }

    /**
     * Warms every scenario up for at least {@code bench.warmupSeconds} (15), then on until the JIT has settled
     * ({@link JitWarmUp}: a pass of all scenarios spends at most 2 % of its time compiling, twice in a row), at most
     * {@code bench.warmupMaxSeconds} (120); the figures are those of a server that has been running a while.
     */
    private static void warmUp(URI uri, TcpEcho echo, RedisPeer redis) throws Exception {
        JitWarmUp.Outcome outcome = JitWarmUp.run(Duration.ofSeconds(Long.getLong("bench.warmupSeconds", 15)),
                Duration.ofSeconds(Long.getLong("bench.warmupMaxSeconds", 120)), 0.02,
                () -> warmUpPass(uri, echo, redis));
        System.out.printf("%s (%s)%n", outcome, CpuPlacement.describe());
    }

    private static void warmUpPass(URI uri, TcpEcho echo, RedisPeer redis) throws Exception {
        tcpRoundTrips(echo);
        if (redis != null) {
            redisCycles(redis);
        }
        writeTakeCycles(uri);
        requestAnswerCycles(uri, false);
        requestAnswerCycles(uri, true);
        requestAnswerCycles(uri, true, JSON_BODIES); // every path warm: each is measured too
        requestAnswerCycles(uri, true, HTTP);
        threadlessModuleCycles(uri);
        notificationLatencies(uri);
        describeCalls(uri);
        jdkHttpCalls(uri);
    }

    /**
     * Runs a scenario {@link #RUNS} times, each right after a batch of TCP round trips, so that each ratio compares
     * figures taken under the same conditions (the echo's own latency varies between runs on a virtual machine).
     */
    private static Row measure(String name, TcpEcho echo, Scenario scenario) throws Exception {
        List<Double> p50s = new ArrayList<>();
        List<Double> p99s = new ArrayList<>();
        List<Double> tcpP50s = new ArrayList<>();
        List<Double> ratios = new ArrayList<>();
        for (int run = 0; run < RUNS; run++) {
            long[] tcp = tcpRoundTrips(echo);
            Arrays.sort(tcp);
            long[] samples = scenario.run();
            Arrays.sort(samples);
            double tcpP50 = percentile(tcp, 0.50) / 1e3;
            double p50 = percentile(samples, 0.50) / 1e3;
            tcpP50s.add(tcpP50);
            p50s.add(p50);
            p99s.add(percentile(samples, 0.99) / 1e3);
            ratios.add(p50 / tcpP50);
        }
        return new Row(name, median(p50s), median(p99s), median(ratios), p50s, tcpP50s);
    }

    private static void print(List<Row> rows) {
        System.out.printf("%n%-58s %8s %8s %7s   %s%n", "scenario", "p50 us", "p99 us", "x TCP",
                "per run: p50 us / TCP p50 just before");
        for (Row row : rows) {
            StringBuilder runs = new StringBuilder();
            for (int i = 0; i < row.runP50s().size(); i++) {
                runs.append(String.format("%.0f/%.0f ", row.runP50s().get(i), row.tcpP50s().get(i)));
            }
            System.out.printf("%-58s %8.1f %8.1f %7.1f   %s%n", row.name(), row.p50(), row.p99(), row.ratio(),
                    runs.toString().trim());
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
