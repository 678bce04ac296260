package robotworld.cluster;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.LockSupport;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import com.fasterxml.jackson.databind.JsonNode;

import robotworld.core.IRDistanceModule;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;
import robotworld.xvsm.CallerSoak;
import robotworld.xvsm.XVSMIRDistanceModuleLocal;
import robotworld.xvsm.XVSMIRDistanceModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * Kill -9 soak of a 3-member clustered space ({@code ./antw bench-cluster-kill}): three {@code rwe space --cluster}
 * processes; {@code bench.hosts} (20) computers with {@code bench.threads} (4) threads each make a module call
 * every {@code bench.callPeriodMillis} (1 000; 0 = as fast as answers come) ({@code getSingleSensor} of {@code bench.modules} IR modules whose answers name module and sensor), each computer
 * a runtime whose client knows all three servers, starting with a different one; writers and takers pass numbered
 * entries through a queue; monitors are subscribed to every operation on that queue. Then {@code bench.kills} (10)
 * times: {@code kill -9} of one member (in turn), calls go on, the member is started again on its ports.
 *
 * <p>Prints per kill how long calls paused (per caller thread, the longest time between two answered calls around
 * the kill), and at the end: mismatched answers, calls past their bound (call timeout plus the network allowance),
 * failed calls by kind, acknowledged writes lost, entries taken twice, notification gaps signalled (a subscription
 * ended OVERFLOWED: "events may be missing", then subscribed again) and silent gaps (a notification whose sequence
 * does not follow the previous one's without such a signal).
 */
public final class ClusterKillSoak {

    private static final int HOSTS = Integer.getInteger("bench.hosts", 20);
    private static final int THREADS = Integer.getInteger("bench.threads", 4);
    private static final int MODULES = Integer.getInteger("bench.modules", 4);
    private static final int KILLS = Integer.getInteger("bench.kills", 10);
    private static final int WRITERS = Integer.getInteger("bench.writers", 4);
    private static final int MONITORS = Integer.getInteger("bench.monitors", 3);
    private static final Duration CALL_TIMEOUT = Duration.ofSeconds(Integer.getInteger("bench.callTimeoutSeconds", 5));
    private static final long ALLOWANCE_MILLIS = RemoteSpace.Options.defaults().networkAllowanceMillis();
    private static final long SETTLE_MILLIS = Long.getLong("bench.settleMillis", 6_000);
    /** How long each writer sleeps after each write. */
    private static final long WRITE_PERIOD_MILLIS = Long.getLong("bench.writePeriodMillis", 50);
    /**
     * How long after a member is started again the next kill waits: its partitions move back to it, its JIT warms
     * up, and the clients that list it first go back to it (once its failure is 10 s old).
     */
    private static final long REJOIN_MILLIS = Long.getLong("bench.rejoinMillis", 12_000);
    /** How often each caller thread starts a call (0: as fast as the answers come, which overloads this machine). */
    private static final long CALL_PERIOD_MILLIS = Long.getLong("bench.callPeriodMillis", 1_000);
    private static final Pattern URL = Pattern.compile("listening on (http://\\S+)");
    private static final Pattern MEMBER = Pattern.compile("cluster member of '[^']+' at (\\S+),");

    private ClusterKillSoak() {
    }

    /** One {@code rwe space --cluster} process. */
    private static final class Member {
        final Process process;
        final String url;
        final String address;

        Member(Process process, String url, String address) {
            this.process = process;
            this.url = url;
            this.address = address;
        }
    }

    private static final String CLUSTER = "rwe-soak-" + Long.toHexString(System.nanoTime());
    private static Path logs;

    private static Member startMember(int index, int httpPort, int memberPort, List<String> join) throws Exception {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-Xmx256m");
        command.add("-Djava.util.logging.config.file=" + memberLogging());
        for (String argument : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (argument.startsWith("--add-")) {
                command.add(argument);
            }
        }
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), "robotworld.explorer.cli.Rwe", "space",
                "--cluster", CLUSTER, "--port", Integer.toString(httpPort), "--member-port",
                Integer.toString(memberPort), "--min-members", "2"));
        if (!join.isEmpty()) {
            command.add("--member");
            command.add(String.join(",", join));
        }
        Process process = new ProcessBuilder(command)
                .redirectError(ProcessBuilder.Redirect.appendTo(logs.resolve("member-" + index + ".log").toFile()))
                .start();
        BufferedReader out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        String url = null;
        String address = null;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (url == null && System.nanoTime() < deadline) {
            String line = out.readLine();
            if (line == null) {
                throw new IllegalStateException("member " + index + " ended; see " + logs);
            }
            Matcher m = MEMBER.matcher(line);
            if (m.find()) {
                address = m.group(1);
            }
            m = URL.matcher(line);
            if (m.find()) {
                url = m.group(1);
            }
        }
        Thread drain = new Thread(() -> {
            try {
                while (out.readLine() != null) {
                    // keep its pipe from filling
                }
            } catch (IOException e) {
                // gone
            }
        }, "member-" + index + "-out");
        drain.setDaemon(true);
        drain.start();
        return new Member(process, url, address);
    }

    /**
     * The members' java.util.logging set-up: this package at DEBUG unless {@code -Dbench.memberDebug=false}, so that
     * a member's log shows its slow cluster calls, troubled waits and partition moves around each kill.
     */
    private static Path memberLogging() throws IOException {
        Path file = logs.resolve("member-logging.properties");
        if (!Files.exists(file)) {
            boolean debug = Boolean.parseBoolean(System.getProperty("bench.memberDebug", "true"));
            Files.writeString(file, String.join("\n",
                    "handlers=java.util.logging.ConsoleHandler",
                    "java.util.logging.ConsoleHandler.level=ALL",
                    "java.util.logging.SimpleFormatter.format=%1$tT.%1$tL %4$s %2$s: %5$s%6$s%n",
                    "robotworld.cluster.level=" + (debug ? "FINE" : "INFO"), ""));
        }
        return file;
    }

    private static int freePort() throws IOException {
        for (int attempt = 0; attempt < 100; attempt++) {
            int port = 20_000 + ThreadLocalRandom.current().nextInt(12_000);
            try (java.net.ServerSocket probe = new java.net.ServerSocket(port, 1,
                    java.net.InetAddress.getLoopbackAddress())) {
                return port;
            } catch (IOException taken) {
                // another one
            }
        }
        throw new IOException("no free port between 20000 and 32000");
    }

    /** Starts a killed member again on its ports, as an operator would; waits while the ports are still held. */
    private static Member restartMember(int index, int httpPort, int memberPort, List<String> join) throws Exception {
        for (int attempt = 1; ; attempt++) {
            try {
                return startMember(index, httpPort, memberPort, join);
            } catch (IllegalStateException e) {
                if (attempt == 10) {
                    throw e;
                }
                Thread.sleep(1_000);
            }
        }
    }

    /**
     * Waits until every member's server says it sees all members and every backup is in place, as an operator does
     * before taking down the next computer; prints how long that took when it was not at once.
     */
    private static void awaitWholeAndSafe(List<Member> members) throws Exception {
        long start = System.nanoTime();
        long deadline = start + TimeUnit.SECONDS.toNanos(120);
        List<String> last = new ArrayList<>();
        while (true) {
            last.clear();
            for (Member member : members) {
                try {
                    JsonNode cluster = HealthProbe.read(URI.create(member.url), Duration.ofSeconds(10))
                            .path("cluster");
                    if (cluster.path("members").asInt() != members.size()
                            || !cluster.path("backupsInPlace").asBoolean()) {
                        last.add(member.url + " " + cluster);
                    }
                } catch (IOException e) {
                    last.add(member.url + " " + e);
                }
            }
            long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
            if (last.isEmpty()) {
                if (waited > 500) {
                    System.out.printf(Locale.ROOT, "         (waited %,d ms for the cluster to be whole and safe)%n",
                            waited);
                }
                return;
            }
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("the cluster is not whole and safe after 120 s: " + last);
            }
            Thread.sleep(200);
        }
    }

    /**
     * Thread dumps of the surviving members into the log folder, to see what their threads wait for while calls are
     * slow to come back: by default at 2.5 and 4 s after a kill whose calls have not yet come back to half their
     * rate; with {@code -Dbench.dumpAfterKillMillis=1000,1500} after every kill at those times ("" for none).
     */
    private static void dumpSurvivors(List<Member> members, Member dead, int kill, long killedAt) throws Exception {
        String asked = System.getProperty("bench.dumpAfterKillMillis");
        String when = asked == null ? "2500,4000" : asked;
        if (when.isBlank()) {
            return;
        }
        for (String each : when.split(",")) {
            long at = killedAt + TimeUnit.MILLISECONDS.toNanos(Long.parseLong(each.trim()));
            long early = at - System.nanoTime();
            if (early > 0) {
                TimeUnit.NANOSECONDS.sleep(early);
            }
            if (asked == null && resumedAfter(killedAt) < TimeUnit.MILLISECONDS.toNanos(SETTLE_MILLIS)) {
                return; // calls came back: nothing to look at
            }
            System.out.printf(Locale.ROOT, "%tT.%<tL calls not back %s ms after kill %d: thread dumps of the"
                    + " survivors into the log folder%n", System.currentTimeMillis(), each.trim(), kill);
            for (int i = 0; i < members.size(); i++) {
                Member member = members.get(i);
                if (member != dead) {
                    new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "jcmd").toString(),
                            Long.toString(member.process.pid()), "Thread.print")
                            .redirectOutput(logs.resolve("dump-kill" + kill + "-member" + i + "-at" + each.trim()
                                    + "ms.txt").toFile())
                            .start();
                }
            }
        }
    }

    private static List<URI> rotated(List<Member> members, int first) {
        List<URI> urls = new ArrayList<>();
        for (int i = 0; i < members.size(); i++) {
            urls.add(URI.create(members.get((first + i) % members.size()).url));
        }
        return urls;
    }

    private static int port(String hostPort) {
        return Integer.parseInt(hostPort.substring(hostPort.lastIndexOf(':') + 1));
    }

    // ---- what the workload records ----

    /** Times (nanoTime) of each caller thread's answered calls. */
    private static final List<ConcurrentLinkedQueue<Long>> answered = new ArrayList<>();
    /** When each write was acknowledged (wall clock, to match the member logs), for the report of lost ones. */
    private static final Map<Long, Long> acknowledgedAt = new ConcurrentHashMap<>();
    /** What the takers' failed calls said, with when: read against the lost writes' times. */
    private static final ConcurrentLinkedQueue<TakerFailure> takerFailures = new ConcurrentLinkedQueue<>();

    private record TakerFailure(long at, String thread, String what) {
    }
    /** When each kill was made (wall clock). */
    private static final List<Long> killedAtMillis = new java.util.concurrent.CopyOnWriteArrayList<>();
    /** When calls of each module were answered: shows whether a slow return is one module's or everyone's. */
    private static final List<ConcurrentLinkedQueue<Long>> answeredByModule = new ArrayList<>();
    private static final AtomicLong mismatches = new AtomicLong();
    private static final AtomicLong pastBound = new AtomicLong();
    /** Calls that gave up at their bound, the thread running a little later than the deadline it woke for. */
    private static final AtomicLong atBound = new AtomicLong();
    /**
     * How late a call that gives up at its deadline may end without counting as past its bound: the thread that
     * notices the deadline is woken by a timer and then needs a CPU, which on two loaded cores takes milliseconds.
     */
    private static final long LATE_MILLIS = 50;
    private static final AtomicLong longestCall = new AtomicLong();
    private static final LongAdder calls = new LongAdder();
    private static final Map<String, LongAdder> failures = new ConcurrentHashMap<>();
    private static final AtomicBoolean running = new AtomicBoolean(true);
    private static final LongAdder gapsSignalled = new LongAdder();
    private static final LongAdder silentGaps = new LongAdder();
    private static final LongAdder notifications = new LongAdder();
    private static final List<String> silentGapDetails = Collections.synchronizedList(new ArrayList<>());
    /** What each call past its bound ended with, and when it started relative to the kill before it. */
    private static final List<String> pastBoundDetails = Collections.synchronizedList(new ArrayList<>());

    public static void main(String[] args) throws Exception {
        // log lines with milliseconds, to be read against the kill times printed below
        System.setProperty("java.util.logging.SimpleFormatter.format", "%1$tT.%1$tL %4$s %2$s: %5$s%6$s%n");
        logs = Files.createTempDirectory("rwe-kill-soak");
        System.out.printf(Locale.ROOT, "Kill -9 soak: 3 cluster members as processes (rwe space --cluster), %d hosts"
                + " x %d threads making module calls (timeout %d s) on %d modules, %d writers, %d monitors, %d kills;"
                + " %s, %d CPUs; member logs in %s%n", HOSTS, THREADS, CALL_TIMEOUT.toSeconds(), MODULES, WRITERS,
                MONITORS, KILLS, System.getProperty("java.vm.version"), Runtime.getRuntime().availableProcessors(),
                logs);
        List<Member> members = new ArrayList<>();
        List<AutoCloseable> closing = new ArrayList<>();
        ExecutorService threads = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r);
            t.setDaemon(true);
            return t;
        });
        try {
            // ports below the ephemeral range, so that a killed member's ports are not handed to some client's
            // connection meanwhile and it can start again on them
            members.add(startMember(0, freePort(), freePort(), List.of()));
            members.add(startMember(1, freePort(), freePort(), List.of(members.get(0).address)));
            members.add(startMember(2, freePort(), freePort(), List.of(members.get(0).address,
                    members.get(1).address)));
            System.out.println("members: " + members.stream().map(m -> m.url + " (" + m.address + ")").toList());
            Thread.sleep(3_000); // partitions spread over the three

            RemoteSpace.Options options = RemoteSpace.Options.defaults();
            // providers: each module served by its own runtime
            for (int m = 0; m < MODULES; m++) {
                answeredByModule.add(new ConcurrentLinkedQueue<>());
                XVSMRuntime provider = XVSMRuntime.using(RemoteSpace.open(rotated(members, m), options),
                        "robot-" + m, true);
                closing.add(provider);
                new XVSMIRDistanceModuleLocal(provider, "Robot" + m, "IR", new CallerSoak.NamedDistances(m), false);
            }
            // callers
            for (int h = 0; h < HOSTS; h++) {
                XVSMRuntime host = XVSMRuntime.using(RemoteSpace.open(rotated(members, h), options), "host-" + h,
                        true);
                closing.add(host);
                for (int t = 0; t < THREADS; t++) {
                    ConcurrentLinkedQueue<Long> times = new ConcurrentLinkedQueue<>();
                    answered.add(times);
                    List<XVSMIRDistanceModuleRemote> modules = new ArrayList<>();
                    for (int m = 0; m < MODULES; m++) {
                        XVSMIRDistanceModuleRemote remote = new XVSMIRDistanceModuleRemote(host, "Robot" + m, "IR");
                        remote.setCallTimeout(CALL_TIMEOUT);
                        modules.add(remote);
                    }
                    threads.execute(() -> callModules(modules, times));
                }
            }
            // queue traffic: writers, takers, monitors
            RemoteSpace setup = RemoteSpace.open(rotated(members, 0), options);
            closing.add(setup);
            ContainerRef queue = setup.lookupOrCreateContainer(ContainerSpec.of(Order.FIFO).named("soak-queue"));
            List<Monitor> monitors = new ArrayList<>();
            for (int i = 0; i < MONITORS; i++) {
                RemoteSpace client = RemoteSpace.open(rotated(members, i), options);
                closing.add(client);
                Monitor monitor = new Monitor(client, queue, threads);
                monitors.add(monitor);
                monitor.subscribe();
            }
            List<Set<Long>> acknowledged = new ArrayList<>();
            List<java.util.concurrent.Future<?>> writersDone = new ArrayList<>();
            for (int w = 0; w < WRITERS; w++) {
                RemoteSpace client = RemoteSpace.open(rotated(members, w), options);
                closing.add(client);
                Set<Long> mine = ConcurrentHashMap.newKeySet();
                acknowledged.add(mine);
                int writer = w;
                writersDone.add(threads.submit(() -> write(client, queue, writer, mine)));
            }
            ConcurrentLinkedQueue<Long> taken = new ConcurrentLinkedQueue<>();
            List<java.util.concurrent.Future<?>> takersDone = new ArrayList<>();
            for (int k = 0; k < 2; k++) {
                RemoteSpace client = RemoteSpace.open(rotated(members, k + 1), options);
                closing.add(client);
                takersDone.add(threads.submit(() -> take(client, queue, taken)));
            }

            Thread.sleep(5_000);
            List<Long> pauses = new ArrayList<>();
            List<Long> resumes = new ArrayList<>();
            for (int kill = 0; kill < KILLS; kill++) {
                int victim = kill % members.size();
                Member dead = members.get(victim);
                awaitWholeAndSafe(members); // the acceptance kills one member of a healthy cluster, not a second fault
                long killedAt = System.nanoTime();
                killedAtMillis.add(System.currentTimeMillis());
                dead.process.destroyForcibly(); // SIGKILL
                System.out.printf(Locale.ROOT, "%tT.%<tL kill %d of member %d (%s)%n", System.currentTimeMillis(),
                        kill + 1, victim, dead.url);
                dead.process.waitFor(30, TimeUnit.SECONDS);
                dumpSurvivors(members, dead, kill + 1, killedAt);
                Thread.sleep(Math.max(0, SETTLE_MILLIS
                        - TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - killedAt)));
                String timeline = timeline(answered, killedAt); // before longestPause, which trims the call times
                StringBuilder byModule = new StringBuilder();
                for (int m = 0; m < answeredByModule.size(); m++) {
                    byModule.append(String.format(Locale.ROOT, "%n           module %d (first server %d): %s", m,
                            m % members.size(), timeline(List.of(answeredByModule.get(m)), killedAt)));
                    answeredByModule.get(m).removeIf(at -> at < killedAt);
                }
                long resumed = resumedAfter(killedAt);
                resumes.add(resumed);
                long pause = longestPause(killedAt - TimeUnit.SECONDS.toNanos(1),
                        killedAt + TimeUnit.MILLISECONDS.toNanos(SETTLE_MILLIS));
                pauses.add(pause);
                System.out.printf(Locale.ROOT, "kill %2d: member %d (%s) killed; calls back to half their rate after"
                        + " %,d ms (%d = not within the %d ms watched); longest wait of one caller thread %,d ms; %,d calls answered so far%n", kill + 1,
                        victim, dead.address, TimeUnit.NANOSECONDS.toMillis(resumed), SETTLE_MILLIS, SETTLE_MILLIS,
                        TimeUnit.NANOSECONDS.toMillis(pause), calls.sum());
                System.out.println("         answered calls per 250 ms from 1 s before the kill: " + timeline
                        + byModule);
                List<String> others = new ArrayList<>();
                for (Member other : members) {
                    if (other != dead) {
                        others.add(other.address);
                    }
                }
                others.add(dead.address);
                members.set(victim, restartMember(victim, port(URI.create(dead.url).getAuthority()),
                        port(dead.address), others));
                Thread.sleep(REJOIN_MILLIS);
            }
            running.set(false);
            for (java.util.concurrent.Future<?> done : writersDone) {
                done.get(60, TimeUnit.SECONDS);
            }
            for (java.util.concurrent.Future<?> done : takersDone) {
                done.get(60, TimeUnit.SECONDS);
            }
            // takes whose answers were lost are held for their lease (10 s): then their entries are back
            Thread.sleep(12_000);
            drain(setup, queue, taken);
            awaitLateOnes(setup, queue, taken, acknowledged);
            threads.shutdown();
            threads.awaitTermination(CALL_TIMEOUT.toSeconds() + ALLOWANCE_MILLIS / 1000 + 10, TimeUnit.SECONDS);

            List<Long> takenList = new ArrayList<>(taken);
            Set<Long> takenSet = new HashSet<>(takenList);
            long lost = 0;
            long written = 0;
            List<String> lostOnes = new ArrayList<>();
            for (Set<Long> mine : acknowledged) {
                written += mine.size();
                for (Long value : new java.util.TreeSet<>(mine)) {
                    if (!takenSet.contains(value)) {
                        lost++;
                        lostOnes.add(describeLost(value, takenSet));
                    }
                }
            }
            long duplicates = takenList.size() - takenSet.size();
            long[] sorted = pauses.stream().mapToLong(TimeUnit.NANOSECONDS::toMillis).sorted().toArray();
            Map<String, Long> failed = new java.util.TreeMap<>();
            failures.forEach((kind, n) -> failed.put(kind, n.sum()));
            System.out.printf(Locale.ROOT, "%nmodule calls answered: %,d; mismatched answers: %d; failed: %s%n",
                    calls.sum(), mismatches.get(), failed.isEmpty() ? "none" : failed);
            System.out.printf(Locale.ROOT, "longest call: %,d ms; calls past their bound (%d s timeout + %d s "
                    + "allowance, + %d ms for the thread to run): %d; ended within %d ms after it: %d%n",
                    longestCall.get(), CALL_TIMEOUT.toSeconds(), ALLOWANCE_MILLIS / 1000, LATE_MILLIS,
                    pastBound.get(), LATE_MILLIS, atBound.get());
            synchronized (pastBoundDetails) {
                pastBoundDetails.stream().limit(10).forEach(detail -> System.out.println("  past its bound: " + detail));
            }
            long[] back = resumes.stream().mapToLong(TimeUnit.NANOSECONDS::toMillis).sorted().toArray();
            System.out.printf(Locale.ROOT, "calls back to half their rate after a kill (ms): median %d, max %d, all"
                    + " %s%n", back[back.length / 2], back[back.length - 1], Arrays.toString(back));
            System.out.printf(Locale.ROOT, "longest wait of one caller thread per kill (ms; a call in flight on the"
                    + " killed member may wait out its timeout): median %d, max %d, all %s%n",
                    sorted[sorted.length / 2], sorted[sorted.length - 1], Arrays.toString(sorted));
            System.out.printf(Locale.ROOT, "queue: %,d writes acknowledged, %,d entries taken, acknowledged writes "
                    + "lost: %d, entries taken twice: %d%n", written, takenList.size(), lost, duplicates);
            lostOnes.stream().limit(20).forEach(line -> System.out.println("  lost: " + line));
            printTakerFailuresAround(acknowledged, takenSet);
            System.out.printf(Locale.ROOT, "monitors: %,d notifications, gaps signalled (subscription ended "
                    + "OVERFLOWED, subscribed again): %d, silent gaps: %d %s%n", notifications.sum(),
                    gapsSignalled.sum(), silentGaps.sum(), silentGapDetails.isEmpty() ? ""
                            : silentGapDetails.subList(0, Math.min(5, silentGapDetails.size())));
            boolean met = mismatches.get() == 0 && pastBound.get() == 0 && lost == 0 && duplicates == 0
                    && silentGaps.sum() == 0 && back[back.length - 1] <= 2_000;
            System.out.println("verdict: zero mismatches, none past its bound, none lost or taken twice, no silent"
                    + " gap, calls back to half their rate within 2 s after every kill: " + (met ? "met" : "NOT met"));
        } finally {
            running.set(false);
            Collections.reverse(closing);
            for (AutoCloseable each : closing) {
                try {
                    each.close();
                } catch (Exception e) {
                    // going anyway
                }
            }
            for (Member member : members) {
                member.process.destroyForcibly();
            }
        }
        System.exit(0);
    }

    private static void callModules(List<XVSMIRDistanceModuleRemote> modules, ConcurrentLinkedQueue<Long> times) {
        long period = TimeUnit.MILLISECONDS.toNanos(CALL_PERIOD_MILLIS);
        // threads start at random points of the period, as independent control loops would
        long next = System.nanoTime() + (period == 0 ? 0 : ThreadLocalRandom.current().nextLong(period));
        while (running.get()) {
            long early = next - System.nanoTime();
            if (early > 0) {
                LockSupport.parkNanos(early);
                continue;
            }
            // a late call starts at once; the loop does not catch up with a burst
            next = Math.max(next + period, System.nanoTime());
            int module = ThreadLocalRandom.current().nextInt(modules.size());
            int sensor = 1 + ThreadLocalRandom.current().nextInt(IRDistanceModule.SENSORS);
            long started = System.nanoTime();
            long startedAtMillis = System.currentTimeMillis();
            String outcome = "answered";
            try {
                int distance = modules.get(module).getSingleSensor(sensor);
                if (distance != CallerSoak.NamedDistances.distance(module, sensor)) {
                    mismatches.incrementAndGet();
                }
                calls.increment();
                long now = System.nanoTime();
                times.add(now);
                answeredByModule.get(module).add(now);
            } catch (RuntimeException e) {
                failures.computeIfAbsent(e.getClass().getSimpleName(), k -> new LongAdder()).increment();
                outcome = e.toString() + (e.getCause() == null ? "" : " <- " + e.getCause());
            }
            long millis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            longestCall.accumulateAndGet(millis, Math::max);
            long bound = CALL_TIMEOUT.toMillis() + ALLOWANCE_MILLIS;
            if (millis > bound + LATE_MILLIS) {
                pastBound.incrementAndGet();
                long sinceKill = -1;
                int kill = 0;
                for (int k = 0; k < killedAtMillis.size(); k++) {
                    if (killedAtMillis.get(k) <= startedAtMillis) {
                        sinceKill = startedAtMillis - killedAtMillis.get(k);
                        kill = k + 1;
                    }
                }
                pastBoundDetails.add(String.format(Locale.ROOT, "%,d ms, module %d, started %,d ms after kill %d: %s",
                        millis, module, sinceKill, kill, outcome));
            } else if (millis > bound) {
                atBound.incrementAndGet();
            }
        }
    }

    /**
     * How long after {@code killedAt} the answered calls of all threads together first reach half the rate they had
     * in the 3 s before (over a sliding 500 ms window).
     */
    private static long resumedAfter(long killedAt) {
        List<Long> all = new ArrayList<>();
        for (ConcurrentLinkedQueue<Long> times : answered) {
            all.addAll(times);
        }
        Collections.sort(all);
        long window = TimeUnit.MILLISECONDS.toNanos(500);
        long before = all.stream().filter(t -> t >= killedAt - TimeUnit.SECONDS.toNanos(3) && t < killedAt).count();
        double wanted = before / 6.0 / 2; // half of the calls of an average 500 ms before the kill
        int from = 0;
        for (int to = 0; to < all.size(); to++) {
            long at = all.get(to);
            if (at < killedAt) {
                continue;
            }
            while (all.get(from) < at - window) {
                from++;
            }
            if (at - killedAt >= window && to - from + 1 >= wanted) {
                return at - killedAt;
            }
        }
        return TimeUnit.MILLISECONDS.toNanos(SETTLE_MILLIS);
    }

    /** Answered calls of all threads per 250 ms, from 1 s before {@code killedAt} to 5 s after it; "|" at the kill. */
    private static String timeline(List<ConcurrentLinkedQueue<Long>> answered, long killedAt) {
        long bucket = TimeUnit.MILLISECONDS.toNanos(250);
        long from = killedAt - 4 * bucket;
        int[] counts = new int[24];
        for (ConcurrentLinkedQueue<Long> times : answered) {
            for (Long at : times) {
                long index = Math.floorDiv(at - from, bucket);
                if (index >= 0 && index < counts.length) {
                    counts[(int) index]++;
                }
            }
        }
        StringBuilder line = new StringBuilder();
        for (int i = 0; i < counts.length; i++) {
            line.append(i == 4 ? " | " : i == 0 ? "" : " ").append(counts[i]);
        }
        return line.toString();
    }

    /** Per caller thread, the longest time without an answered call within [from, to]; the longest of them all. */
    private static long longestPause(long from, long to) {
        long longest = 0;
        for (ConcurrentLinkedQueue<Long> times : answered) {
            long previous = from;
            for (Long at : times) {
                if (at < from) {
                    continue;
                }
                if (at > to) {
                    break;
                }
                longest = Math.max(longest, at - previous);
                previous = at;
            }
            longest = Math.max(longest, Math.max(0, Math.min(to, System.nanoTime()) - previous));
            times.removeIf(at -> at < to - TimeUnit.SECONDS.toNanos(1));
        }
        return longest;
    }

    /**
     * Acknowledged writes not taken by now may be held rather than lost (served to an operation nobody collects):
     * looks again every 10 s for up to two and a half minutes, longer than anything is held, and says what came back
     * when, so that the count of lost writes below is only of those that never came back.
     */
    private static void awaitLateOnes(Capi setup, ContainerRef queue, ConcurrentLinkedQueue<Long> taken,
                                      List<Set<Long>> acknowledged) throws InterruptedException {
        long start = System.nanoTime();
        while (true) {
            Set<Long> seen = new HashSet<>(taken);
            long missing = acknowledged.stream().flatMap(Set::stream).filter(value -> !seen.contains(value)).count();
            long waited = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - start);
            if (missing == 0 || waited >= 150) {
                if (waited > 0) {
                    System.out.printf(Locale.ROOT, "after %d s more: %d acknowledged writes still missing%n", waited,
                            missing);
                }
                return;
            }
            System.out.printf(Locale.ROOT, "%d acknowledged writes missing %d s after the drain; looking again in"
                    + " 10 s%n", missing, waited);
            Thread.sleep(10_000);
            drain(setup, queue, taken);
        }
    }

    /** The takers' failed calls from 2 s before the first lost write was acknowledged to 15 s after the last. */
    private static void printTakerFailuresAround(List<Set<Long>> acknowledged, Set<Long> taken) {
        long first = Long.MAX_VALUE;
        long last = Long.MIN_VALUE;
        for (Set<Long> mine : acknowledged) {
            for (Long value : mine) {
                Long at = acknowledgedAt.get(value);
                if (!taken.contains(value) && at != null) {
                    first = Math.min(first, at);
                    last = Math.max(last, at);
                }
            }
        }
        if (first == Long.MAX_VALUE) {
            return;
        }
        for (TakerFailure failure : takerFailures) {
            if (failure.at() >= first - 2_000 && failure.at() <= last + 15_000) {
                System.out.printf(Locale.ROOT, "  taker failure %tT.%<tL %s: %s%n", failure.at(), failure.thread(),
                        failure.what());
            }
        }
    }

    /** A lost write: which writer, when it was acknowledged against the kill before it, whether its neighbours came. */
    private static String describeLost(long value, Set<Long> taken) {
        long at = acknowledgedAt.getOrDefault(value, 0L);
        long sinceKill = -1;
        int kill = 0;
        for (int i = 0; i < killedAtMillis.size(); i++) {
            if (killedAtMillis.get(i) <= at) {
                sinceKill = at - killedAtMillis.get(i);
                kill = i + 1;
            }
        }
        return String.format(Locale.ROOT, "writer %d, write %d, acknowledged %tT.%<tL (%s); previous %s, next %s",
                value / 1_000_000_000L, value % 1_000_000_000L, at,
                kill == 0 ? "before the first kill" : sinceKill + " ms after kill " + kill,
                taken.contains(value - 1) ? "taken" : "not taken", taken.contains(value + 1) ? "taken" : "not taken");
    }

    private static void write(Capi client, ContainerRef queue, int writer, Set<Long> acknowledged) {
        for (long i = 1; running.get(); i++) {
            long value = writer * 1_000_000_000L + i;
            try {
                client.write(queue, Timeout.TRY_ONCE, Entry.of(value));
                acknowledged.add(value);
                acknowledgedAt.put(value, System.currentTimeMillis());
            } catch (SpaceException e) {
                // outcome unknown: not counted as acknowledged (it may still be there)
            }
            sleep(WRITE_PERIOD_MILLIS);
        }
    }

    private static void take(Capi client, ContainerRef queue, ConcurrentLinkedQueue<Long> taken) {
        while (running.get()) {
            try {
                for (Entry entry : client.take(queue, Timeout.ofMillis(1_000), Selector.fifo(5))) {
                    taken.add(((IntEntry) entry).value());
                }
            } catch (SpaceTimeoutException e) {
                // nothing there yet
            } catch (SpaceException e) {
                // the server moves: what a lost take held comes back after its lease
                takerFailures.add(new TakerFailure(System.currentTimeMillis(), Thread.currentThread().getName(),
                        e.getClass().getSimpleName() + ": " + e.getMessage()
                        + (e.getCause() == null ? "" : " (" + e.getCause() + ")")));
            }
        }
    }

    /** Takes what is left; tries again for a while if the cluster is still busy settling the last restart. */
    private static void drain(Capi client, ContainerRef queue, ConcurrentLinkedQueue<Long> taken) {
        for (int attempt = 1; ; attempt++) {
            try {
                for (Entry entry : client.take(queue, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL))) {
                    taken.add(((IntEntry) entry).value());
                }
                return;
            } catch (SpaceException e) {
                if (attempt == 30) {
                    throw e;
                }
                System.out.println("draining the queue: " + e.getMessage() + "; again in 1 s");
                sleep(1_000);
            }
        }
    }

    /**
     * A subscriber to every operation on the queue, as a monitor is: notifications must follow each other by
     * sequence; when its subscription ends OVERFLOWED (events may be missing), it counts the signal and subscribes
     * again.
     */
    private static final class Monitor implements NotificationListener {
        private final Capi client;
        private final ContainerRef queue;
        private final ExecutorService threads;
        private long last = -1;

        Monitor(Capi client, ContainerRef queue, ExecutorService threads) {
            this.client = client;
            this.queue = queue;
            this.threads = threads;
        }

        void subscribe() {
            synchronized (this) {
                last = -1;
            }
            while (running.get()) {
                try {
                    client.subscribe(queue, Operation.any(), NotificationMode.INFINITE, Timeout.INFINITE, this);
                    return;
                } catch (SpaceException e) {
                    sleep(100);
                }
            }
        }

        @Override
        public synchronized void onNotification(Notification notification) {
            notifications.increment();
            if (last >= 0 && notification.sequence() != last + 1) {
                silentGaps.increment();
                silentGapDetails.add(last + "->" + notification.sequence() + " " + notification.operation());
            }
            last = notification.sequence();
        }

        @Override
        public void onEnd(SubscriptionEnd reason) {
            if (reason == SubscriptionEnd.OVERFLOWED) {
                gapsSignalled.increment();
            }
            if (running.get()) {
                threads.execute(this::subscribe);
            }
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
