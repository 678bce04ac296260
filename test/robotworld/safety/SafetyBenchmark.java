package robotworld.safety;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.server.SpaceServer;
import robotworld.xvsm.ActuatorStoppedException;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * Safety benchmark ({@code ./antw bench-safety}): for every way an actuator is stopped, the time from the event to
 * the simulated motor module's set speed reading 0, p50 and max over {@code bench.trials} (20) trials, beside the
 * configured timeout and the goal; then what the safety layer costs: bus time of the watchdog heartbeats of an idle
 * module (simulator with real line timing), and module-call latency with and without heartbeats in the same run.
 *
 * <p>The module is polled every 0.1 ms from this JVM, which also causes each event (a call, a signal to a child
 * JVM, closing the space server), so both ends use the same clock. Paths: close of the runtime; failed(...) for an
 * uncaught exception; SIGTERM of the serving program (a child JVM); SIGKILL of it (the module's watchdog, 500 ms);
 * SIGKILL of a remote commander (command timeout 500 ms); the space server closed while a remote commander drives
 * the motor (command timeout 500 ms);
 * {@code rwe stop} from a third program (a {@link WorldStop} over its own connection). Arguments, or
 * {@code -Dbench.paths=a,b}, name the parts to run (close, exception, sigterm, sigkill, commander, space, stop, bus,
 * calls); none: all. Knobs: {@code bench.trials}, {@code bench.callRuns}, {@code bench.calls},
 * {@code bench.idleSeconds}.
 */
public final class SafetyBenchmark {

    private static final int TRIALS = Integer.getInteger("bench.trials", 20);
    private static final int CALL_RUNS = Integer.getInteger("bench.callRuns", 7);
    /** The JIT needs tens of thousands of calls on a small machine before the HTTP path settles. */
    private static final long WARMUP_SECONDS = Long.getLong("bench.warmupSeconds", 10);
    private static final int CALLS = Integer.getInteger("bench.calls", 500);
    private static final Duration START = Duration.ofSeconds(60);
    private static final long POLL_NANOS = 100_000;

    private interface Trial {
        /** Prepares one trial (the motors run) and returns the event, which the benchmark causes and times. */
        Event prepare(SafetyRig rig) throws Exception;
    }

    private interface Event {
        void cause() throws Exception;
    }

    /** One path's figures; the goal is judged twice: on the p50 (the typical stop) and on the max (every trial). */
    private record Row(String path, String timeout, double p50, double max, int trials, String goal, boolean p50Met,
                       boolean maxMet) {
    }

    private static final List<Row> ROWS = new ArrayList<>();
    private static Path temp;

    private SafetyBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        List<String> only = args.length > 0 ? Arrays.asList(args)
                : Arrays.stream(System.getProperty("bench.paths", "").split(",")).filter(p -> !p.isBlank()).toList();
        temp = Files.createTempDirectory("bench-safety");
        System.out.printf(Locale.ROOT, "Safety benchmark, %s, Java %s, %d CPUs, %d trials per path%n%n",
                System.getProperty("os.name"), System.getProperty("java.version"),
                Runtime.getRuntime().availableProcessors(), TRIALS);
        try (SafetyRig rig = SafetyRig.start()) {
            if (wanted(only, "close")) {
                path(rig, "clean exit: runtime closed", "-", 100, SafetyBenchmark::closeTrial);
            }
            if (wanted(only, "exception")) {
                path(rig, "clean exit: uncaught exception", "-", 100, SafetyBenchmark::exceptionTrial);
            }
            if (wanted(only, "sigterm")) {
                path(rig, "clean exit: SIGTERM (child JVM)", "-", 100, SafetyBenchmark::sigtermTrial);
            }
            if (wanted(only, "sigkill")) {
                path(rig, "SIGKILL of the program: bus watchdog", "watchdog 500 ms", 550, SafetyBenchmark::sigkillTrial);
            }
            if (wanted(only, "commander")) {
                path(rig, "remote commander killed (SIGKILL)", "command 500 ms", 600, SafetyBenchmark::commanderTrial);
            }
            if (commanderProvider != null) {
                commanderProvider.close();
            }
            if (wanted(only, "space")) {
                path(rig, "space server closed", "command 500 ms", 600, SafetyBenchmark::spaceTrial);
            }
            if (wanted(only, "stop")) {
                stopPath(rig);
            }
            printTable();
            if (wanted(only, "calls")) {
                callLatency(rig);
            }
        }
        if (wanted(only, "bus")) {
            busCost();
        }
    }

    private static boolean wanted(List<String> only, String path) {
        return only.isEmpty() || only.contains(path);
    }

    // ----- the paths -----

    private static Event closeTrial(SafetyRig rig) throws Exception {
        XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
        XVSMMotorModuleLocal motor = serveMotor(runtime, rig);
        motor.setMotor(1, 0.45);
        motor.setMotor(2, 0.45);
        return runtime::close;
    }

    private static Event exceptionTrial(SafetyRig rig) throws Exception {
        XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
        XVSMMotorModuleLocal motor = serveMotor(runtime, rig);
        motor.setMotor(1, 0.45);
        motor.setMotor(2, 0.45);
        closeLater(runtime);
        return () -> runtime.failed(new IllegalStateException("benchmark"));
    }

    private static Event sigtermTrial(SafetyRig rig) throws Exception {
        ChildProgram child = ChildProgram.start(temp, List.of(), SafetyChild.class, "serve", "wait", rig.spaceUrl,
                rig.busPort);
        child.awaitLine("READY", START);
        closeLater(child);
        return child::terminate;
    }

    private static Event sigkillTrial(SafetyRig rig) throws Exception {
        ChildProgram child = ChildProgram.start(temp, List.of(), SafetyChild.class, "serve", "wait", rig.spaceUrl,
                rig.busPort);
        child.awaitLine("READY", START);
        closeLater(child);
        return child::kill;
    }

    private static XVSMRuntime commanderProvider;

    private static Event commanderTrial(SafetyRig rig) throws Exception {
        if (commanderProvider == null) {
            commanderProvider = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
            serveMotor(commanderProvider, rig);
        }
        ChildProgram commander = ChildProgram.start(temp, List.of(), SafetyChild.class, "command", rig.spaceUrl,
                "0.45");
        commander.awaitLine("READY", START);
        closeLater(commander);
        return commander::kill;
    }

    private static Event spaceTrial(SafetyRig rig) throws Exception {
        SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(0));
        XVSMRuntime runtime = XVSMRuntime.connect(server.uri().toString(), "robot-pc");
        serveMotor(runtime, rig);
        // commanded through the space: what only the serving program commands is not stopped for a lost space
        XVSMRuntime laptop = XVSMRuntime.connect(server.uri().toString(), "laptop");
        XVSMMotorModuleRemote motor = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT, SafetyRig.MOTOR));
        motor.setMotor(1, 0.45);
        motor.setMotor(2, 0.45);
        Thread.sleep(300); // heartbeats under way
        closeLater(laptop);
        closeLater(runtime);
        return server::close;
    }

    private static void stopPath(SafetyRig rig) throws Exception {
        try (XVSMRuntime provider = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
             XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop");
             robotworld.space.Capi ops = robotworld.space.remote.RemoteSpace.open(rig.space.uri())) {
            serveMotor(provider, rig);
            XVSMMotorModuleRemote motor = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT,
                    SafetyRig.MOTOR));
            List<WorldStop.Target> targets = List.of(new WorldStop.Target(SafetyRig.ROBOT, SafetyRig.MOTOR, true));
            List<Double> answered = java.util.Collections.synchronizedList(new ArrayList<>());
            path(rig, "rwe stop from a third program", "-", 100, r -> {
                try {
                    motor.setMotor(1, 0.45);
                } catch (ActuatorStoppedException told) {
                    motor.setMotor(1, 0.45);
                }
                motor.setMotor(2, 0.45);
                return () -> {
                    WorldStop.Result result = WorldStop.stop(ops, "bench", "", targets, Duration.ofSeconds(5));
                    answered.add(result.elapsed().toNanos() / 1e6);
                };
            });
            Collections.sort(answered);
            System.out.printf(Locale.ROOT, "      (rwe stop had every answer after p50 %.1f ms, max %.1f ms)%n%n",
                    percentile(answered, 50), answered.get(answered.size() - 1));
        }
    }

    // ----- measuring -----

    private static void path(SafetyRig rig, String name, String timeout, double goalMillis, Trial trial)
            throws Exception {
        System.out.printf(Locale.ROOT, "  %-40s", name);
        List<Double> millis = new ArrayList<>();
        for (int i = 0; i < TRIALS; i++) {
            Event event = prepare(rig, trial);
            // the event runs on a thread of its own (a close may go on long after the motors stopped): this one
            // watches the module meanwhile
            java.util.concurrent.atomic.AtomicLong caused = new java.util.concurrent.atomic.AtomicLong();
            Thread causing = new Thread(() -> {
                caused.set(System.nanoTime());
                try {
                    event.cause();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, "bench event");
            causing.start();
            while (caused.get() == 0) {
                Thread.onSpinWait();
            }
            long stopped = awaitStopped(rig, caused.get());
            causing.join();
            millis.add((stopped - caused.get()) / 1e6);
            System.out.print(".");
            System.out.flush();
            awaitQuiet(rig);
        }
        Collections.sort(millis);
        double p50 = percentile(millis, 50);
        double max = millis.get(millis.size() - 1);
        ROWS.add(new Row(name, timeout, p50, max, millis.size(), "<= " + (int) goalMillis + " ms", p50 <= goalMillis,
                max <= goalMillis));
        System.out.printf(Locale.ROOT, " p50 %.1f ms, max %.1f ms   (all: %s)%n", p50, max, format(millis));
    }

    /** Prepares a trial; a set-up that fails (a busy machine: a bus reply too late) is tried again, twice. */
    private static Event prepare(SafetyRig rig, Trial trial) throws Exception {
        for (int attempt = 1; ; attempt++) {
            try {
                return trial.prepare(rig);
            } catch (Exception e) {
                if (attempt == 3) {
                    throw e;
                }
                System.out.print("x");
                awaitQuiet(rig);
            }
        }
    }

    /** Polls the module until both wheel motors read 0; returns when (nanoTime). */
    private static long awaitStopped(SafetyRig rig, long event) {
        while (!rig.motorsStopped()) {
            if (System.nanoTime() - event > Duration.ofSeconds(30).toNanos()) {
                throw new IllegalStateException("the motors did not stop within 30 s");
            }
            LockSupport.parkNanos(POLL_NANOS);
        }
        return System.nanoTime();
    }

    /** Lets the previous trial's programs end before the next one starts, so trials do not overlap. */
    private static void awaitQuiet(SafetyRig rig) throws InterruptedException {
        for (AutoCloseable leftover : LATER) {
            try {
                leftover.close();
            } catch (Exception e) {
                // best effort
            }
        }
        LATER.clear();
        Thread.sleep(200);
    }

    private static final List<AutoCloseable> LATER = new ArrayList<>();

    private static void closeLater(AutoCloseable resource) {
        LATER.add(resource);
    }

    private static void printTable() {
        System.out.println();
        System.out.printf(Locale.ROOT, "| %-40s | %-16s | %6s | %8s | %8s | %-9s | %s | %s |%n", "path", "timeout",
                "trials", "p50 ms", "max ms", "goal", "p50 met", "max met");
        System.out.println("|" + "-".repeat(42) + "|" + "-".repeat(18) + "|" + "-".repeat(8) + "|" + "-".repeat(10)
                + "|" + "-".repeat(10) + "|" + "-".repeat(11) + "|---------|---------|");
        for (Row row : ROWS) {
            System.out.printf(Locale.ROOT, "| %-40s | %-16s | %6d | %8.1f | %8.1f | %-9s | %-7s | %-7s |%n",
                    row.path(), row.timeout(), row.trials(), row.p50(), row.max(), row.goal(),
                    row.p50Met() ? "yes" : "NO", row.maxMet() ? "yes" : "NO");
        }
        System.out.println();
    }

    // ----- what it costs -----

    /**
     * Remote call latency with and without heartbeats, interleaved runs in one JVM: a remote bumper read (a sensor:
     * its serving program polls no commander) and a remote setMotor (an engaged motor: its serving program reads the
     * commander's heartbeat every 50 ms).
     */
    private static void callLatency(SafetyRig rig) throws Exception {
        System.out.println("Module-call latency with heartbeats (100 ms) and without (rwe.heartbeat.ms=0): "
                + WARMUP_SECONDS + " s warm-up, then " + CALL_RUNS + " pairs of runs of " + CALLS
                + " calls each, new programs per run; p50 in µs, and the median of the per-pair ratios:");
        // about latency, not stops: no watchdog or command timeout a busy machine could reach
        System.setProperty("rwe.watchdog.ms.SafetyBot.Motor", "10000");
        System.setProperty("rwe.command.timeout.ms", "60000");
        long warmUntil = System.nanoTime() + Duration.ofSeconds(WARMUP_SECONDS).toNanos();
        boolean heartbeats = true;
        while (System.nanoTime() - warmUntil < 0) {
            System.setProperty("rwe.heartbeat.ms", heartbeats ? "100" : "0");
            remoteCalls(rig);
            heartbeats = !heartbeats;
        }
        List<Double> bumperOn = new ArrayList<>();
        List<Double> bumperOff = new ArrayList<>();
        List<Double> motorOn = new ArrayList<>();
        List<Double> motorOff = new ArrayList<>();
        for (int run = 0; run < CALL_RUNS; run++) {
            // alternate which goes first, so that a drift of the machine does not favour one
            for (boolean on : run % 2 == 0 ? new boolean[] {true, false} : new boolean[] {false, true}) {
                System.setProperty("rwe.heartbeat.ms", on ? "100" : "0");
                double[] p50 = remoteCalls(rig);
                (on ? bumperOn : bumperOff).add(p50[0]);
                (on ? motorOn : motorOff).add(p50[1]);
            }
        }
        System.clearProperty("rwe.heartbeat.ms");
        System.clearProperty("rwe.watchdog.ms.SafetyBot.Motor");
        System.clearProperty("rwe.command.timeout.ms");
        report("remote getAllBumper", bumperOn, bumperOff);
        report("remote setMotor (engaged)", motorOn, motorOff);
        System.out.println();
    }

    private static void report(String call, List<Double> on, List<Double> off) {
        List<Double> ratios = new ArrayList<>();
        for (int i = 0; i < on.size(); i++) {
            ratios.add(on.get(i) / off.get(i));
        }
        System.out.printf(Locale.ROOT, "  %-28s with %7.1f  without %7.1f  ratio %.2f   (runs: with %s; without %s)%n",
                call, median(on), median(off), median(ratios), format(on), format(off));
    }

    private static double[] remoteCalls(SafetyRig rig) throws Exception {
        try (XVSMRuntime provider = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
             XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop")) {
            RS485Bus bus = serveBus(provider, rig);
            provider.own(new XVSMMotorModuleLocal(provider, SafetyRig.ROBOT, SafetyRig.MOTOR,
                    new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
            provider.own(new XVSMBumperModuleLocal(provider, SafetyRig.ROBOT, SafetyRig.BUMPER,
                    new BumperModuleProxy(bus, 2, SafetyRig.BUMPER), false));
            XVSMBumperModuleRemote bumper = laptop.own(new XVSMBumperModuleRemote(laptop, SafetyRig.ROBOT,
                    SafetyRig.BUMPER));
            XVSMMotorModuleRemote motor = laptop.own(new XVSMMotorModuleRemote(laptop, SafetyRig.ROBOT,
                    SafetyRig.MOTOR));
            List<Double> bumperMicros = new ArrayList<>();
            List<Double> motorMicros = new ArrayList<>();
            for (int i = 0; i < CALLS; i++) {
                long start = System.nanoTime();
                bumper.getAllBumper();
                bumperMicros.add((System.nanoTime() - start) / 1e3);
                start = System.nanoTime();
                motor.setMotor(1, i % 2 == 0 ? 0.2 : 0.3);
                motorMicros.add((System.nanoTime() - start) / 1e3);
            }
            motor.setMotor(1, 0);
            return new double[] {median(bumperMicros), median(motorMicros)};
        }
    }

    /**
     * Bus time the watchdog heartbeats of idle modules take: the simulator at real line timing (115200 baud), one
     * and four armed modules, nothing else on the bus for {@code bench.idleSeconds} (10).
     */
    private static void busCost() throws Exception {
        long seconds = Long.getLong("bench.idleSeconds", 10);
        System.out.println("Bus time of the watchdog heartbeats of idle modules (simulator, real timing, 115200 8N1, "
                + "watchdog 500 ms, " + seconds + " s idle):");
        String config = SafetyRig.ROBOT_CONFIG.replace("timing=\"fast\"", "timing=\"real\"")
                .replace("<Servo address=\"3\" speed=\"90\"/>", "<Servo address=\"3\" speed=\"90\"/>"
                        + "<Motor address=\"5\" ramp=\"0\"/><Motor address=\"6\" ramp=\"0\"/>");
        try (SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.parse(config, "bus cost robot"))) {
            String port = robot.serve("tcp://127.0.0.1:0");
            for (int modules : new int[] {1, 4}) {
                try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(115_200), BusTiming.defaults())) {
                    int[] addresses = {1, 3, 5, 6};
                    for (int i = 0; i < modules; i++) {
                        bus.armWatchdog(addresses[i], Duration.ofMillis(500), detail -> { });
                    }
                    long before = bus.watchdog().heartbeats();
                    long start = System.nanoTime();
                    Thread.sleep(seconds * 1000);
                    double elapsed = (System.nanoTime() - start) / 1e9;
                    long beats = bus.watchdog().heartbeats() - before;
                    // a heartbeat: request 8 bytes, reply 6 bytes, each frame followed by 3.5 characters of silence;
                    // a character is 10 bits in 8N1
                    double wire = beats * (8 + 6 + 2 * 3.5) * (10.0 / 115_200);
                    System.out.printf(Locale.ROOT, "  %d armed module(s): %.1f heartbeats/s (%.1f per module), "
                            + "%.2f ms of line time each, %.2f %% of the bus%n", modules, beats / elapsed,
                            beats / elapsed / modules, wire / beats * 1000, 100 * wire / elapsed);
                    for (int i = 0; i < modules; i++) {
                        if (robot.module(addresses[i]).watchdogTripped()) {
                            System.out.println("  (!) module " + addresses[i] + " tripped while fed");
                        }
                    }
                }
            }
        }
        System.out.println();
    }

    // ----- helpers -----

    private static RS485Bus serveBus(XVSMRuntime runtime, SafetyRig rig) throws Exception {
        return runtime.own(new RS485Bus(rig.busPort, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO)));
    }

    private static XVSMMotorModuleLocal serveMotor(XVSMRuntime runtime, SafetyRig rig) throws Exception {
        return runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT, SafetyRig.MOTOR,
                new MotorModuleProxy(serveBus(runtime, rig), 1, SafetyRig.MOTOR)));
    }

    private static double percentile(List<Double> sorted, int percent) {
        int index = (int) Math.ceil(sorted.size() * percent / 100.0) - 1;
        return sorted.get(Math.max(0, index));
    }

    private static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        Collections.sort(sorted);
        return sorted.get((sorted.size() - 1) / 2);
    }

    private static String format(List<Double> values) {
        return String.join(" ", values.stream().map(v -> String.format(Locale.ROOT, "%.0f", v)).toList());
    }
}
