package robotworld.explorer.monitor;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import javax.swing.SwingUtilities;
import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.core.BumperModule;
import robotworld.core.MotorModule;
import robotworld.core.X10ApplianceModule;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.observe.AnswerSeen;
import robotworld.observe.GroundTruth;
import robotworld.observe.WorldObserver;
import robotworld.sim.robot.GroundTruthFeed;
import robotworld.sim.robot.LineTiming;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.ProjectFiles;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMX10ApplianceModuleLocal;
import robotworld.xvsm.XVSMX10ApplianceModuleRemote;

/**
 * {@code ./antw bench-monitor}: what watching costs.
 * <ol>
 *   <li>Ground truth and the bus: bumper reads on the simulated robot's bus with the 20 Hz ground-truth feed
 *       publishing into a space and without it, alternating, {@code bench.monitor.rounds} (5) rounds of 2 000
 *       reads; median p50/p99 and their ratio.</li>
 *   <li>Rendering cost: the monitor window in a JVM of its own, watching the chapter-5 world served as the demo
 *       serves it (simulated robot with ground truth, motor and bumper Local sides on its bus, the lamp), under
 *       three loads: idle (nothing happens), the demo's control loop (listing 5.2's calls, polling every 100 ms)
 *       and the same loop flat out (no pauses). Its process CPU time over {@code bench.monitor.seconds} (20) s,
 *       as a share of one core, and how many of the answers made it saw; median of {@code bench.monitor.rounds}
 *       (3) rounds.</li>
 * </ol>
 * {@code ./antw bench-monitor-soak} runs {@link MonitorSoak} instead: plots fed at 50 Hz for 10 minutes.
 */
public final class MonitorBenchmark {

    private static final int SECONDS = Integer.getInteger("bench.monitor.seconds", 20);
    /** Extra options for the monitor's JVM, space-separated (e.g. a flight recording, to see where its time goes). */
    private static final String CHILD_JVM_ARGS = System.getProperty("bench.monitor.childJvmArgs", "");
    /** Which loads of the rendering cost to measure, comma-separated ({@code idle,demo,flat_out}); all by default. */
    private static final String LOADS = System.getProperty("bench.monitor.loads", "");
    /**
     * Seconds the window runs under its load before it is measured: the JIT compilers work for about half a minute
     * after the window opens (half the process's CPU time at 4 s to 26 s), and the figure is about the steady state.
     */
    private static final int WARM_UP = Integer.getInteger("bench.monitor.warmupSeconds", 30);

    private MonitorBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("child")) {
            Child.run(args[1], Path.of(args[2]), Integer.parseInt(args[3]));
            return;
        }
        System.out.printf(Locale.ROOT, "Monitor benchmark: %s, Java %s, %d CPUs, display %s%n%n",
                System.getProperty("os.name"), System.getProperty("java.version"),
                Runtime.getRuntime().availableProcessors(), System.getenv("DISPLAY"));
        groundTruthAndTheBus(Integer.getInteger("bench.monitor.rounds", 5));
        renderingCost(Integer.getInteger("bench.monitor.rounds", 3));
    }

    // ---- 1: the feed does not slow the bus ----

    private static void groundTruthAndTheBus(int rounds) throws Exception {
        List<Double> offP50 = new ArrayList<>();
        List<Double> offP99 = new ArrayList<>();
        List<Double> onP50 = new ArrayList<>();
        List<Double> onP99 = new ArrayList<>();
        try (SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.read(ProjectFiles.resolve(
                "docs/examples/simulated-robot.sim")).withTiming(LineTiming.FAST));
             RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                     BusTiming.defaults());
             EmbeddedSpace space = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0))) {
            BumperModule bumper = new BumperModuleProxy(bus, 2);
            reads(bumper, 2_000); // warm up
            for (int round = 0; round < rounds; round++) {
                double[] off = reads(bumper, 2_000);
                offP50.add(off[0]);
                offP99.add(off[1]);
                try (var connection = RemoteSpace.open(server.uri());
                     GroundTruthFeed feed = GroundTruthFeed.start(robot, "CaterpillarRobot", connection,
                             GroundTruthFeed.DEFAULT_PERIOD)) {
                    double[] on = reads(bumper, 2_000);
                    onP50.add(on[0]);
                    onP99.add(on[1]);
                }
            }
        }
        System.out.printf(Locale.ROOT, "Ground truth and the bus: getAllBumper over tcp:// (fast timing), %d rounds "
                + "x 2000 reads, medians (us)%n", rounds);
        System.out.printf(Locale.ROOT, "  %-44s p50 %7.1f   p99 %7.1f%n", "feed off", median(offP50), median(offP99));
        System.out.printf(Locale.ROOT, "  %-44s p50 %7.1f   p99 %7.1f%n", "feed on (20 frames/s into a space server)",
                median(onP50), median(onP99));
        System.out.printf(Locale.ROOT, "  ratio on/off: p50 %.2f, p99 %.2f%n%n", median(onP50) / median(offP50),
                median(onP99) / median(offP99));
    }

    private static double[] reads(BumperModule bumper, int count) {
        long[] nanos = new long[count];
        for (int i = 0; i < count; i++) {
            long start = System.nanoTime();
            bumper.getAllBumper();
            nanos[i] = System.nanoTime() - start;
        }
        Arrays.sort(nanos);
        return new double[] {nanos[count / 2] / 1e3, nanos[(int) (count * 0.99)] / 1e3};
    }

    // ---- 2: the monitor window's CPU ----

    private enum Load { IDLE, DEMO, FLAT_OUT }

    private static void renderingCost(int rounds) throws Exception {
        Path world = ProjectFiles.resolve("docs/examples/chapter5-world.xml");
        System.out.printf(Locale.ROOT, "Rendering cost: the monitor window (1360 x 900) in its own JVM, %d s measured "
                + "after %d s, %d rounds, medians%n", SECONDS, WARM_UP, rounds);
        System.out.printf(Locale.ROOT, "  %-38s %10s %12s %10s %14s %10s%n", "load", "calls/s", "CPU % core",
                "JIT % core", "answers seen", "paints/s");
        for (Load load : Load.values()) {
            if (!LOADS.isBlank() && !List.of(LOADS.toLowerCase(Locale.ROOT).split(",")).contains(
                    load.name().toLowerCase(Locale.ROOT))) {
                continue;
            }
            List<Double> cpu = new ArrayList<>();
            List<Double> rates = new ArrayList<>();
            List<Double> paints = new ArrayList<>();
            List<Double> jit = new ArrayList<>();
            long seen = 0;
            long made = 0;
            for (int round = 0; round < rounds; round++) {
                double[] result = renderingRound(world, load);
                cpu.add(result[0]);
                rates.add(result[1]);
                seen += (long) result[2];
                made += (long) result[3];
                paints.add(result[4]);
                jit.add(result[5]);
            }
            System.out.printf(Locale.ROOT, "  %-38s %10.0f %12.1f %10.1f %14s %10.1f%n", label(load), median(rates),
                    median(cpu), median(jit), seen + " of " + made, median(paints));
        }
    }

    private static String label(Load load) {
        return switch (load) {
            case IDLE -> "idle (no calls, no ground truth)";
            case DEMO -> "demo loop (listing 5.2) + 20 Hz truth";
            case FLAT_OUT -> "demo loop flat out + 20 Hz truth";
        };
    }

    /** {cpuPercent, callsPerSecond, answersSeen, answersMade, paintsPerSecond, jitPercent}. */
    private static double[] renderingRound(Path world, Load load) throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.read(ProjectFiles.resolve(
                "docs/examples/demo-robot.sim")).withTiming(LineTiming.FAST));
             RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                     BusTiming.defaults());
             EmbeddedSpace space = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0));
             XVSMRuntime robotLaptop = XVSMRuntime.using(RemoteSpace.open(server.uri()), "robot-laptop", true);
             XVSMRuntime room = XVSMRuntime.using(RemoteSpace.open(server.uri()), "room-pc", true);
             XVSMRuntime laptop = XVSMRuntime.using(RemoteSpace.open(server.uri()), "laptop", true);
             var feedSpace = RemoteSpace.open(server.uri())) {
            new XVSMMotorModuleLocal(robotLaptop, "CaterpillarRobot", "Motor-Controller", new MotorModuleProxy(bus, 1));
            new XVSMBumperModuleLocal(robotLaptop, "CaterpillarRobot", "Bumper-Sensor", new BumperModuleProxy(bus, 2));
            new XVSMX10ApplianceModuleLocal(room, "DimRoom", "Lamp", new X10ApplianceModule() {
                @Override
                public void on() {
                }

                @Override
                public void off() {
                }
            });
            List<String> command = new ArrayList<>(List.of(javaCommand(), "-Xmx512m"));
            if (!CHILD_JVM_ARGS.isBlank()) {
                command.addAll(List.of(CHILD_JVM_ARGS.trim().split("\\s+")));
            }
            command.addAll(List.of("-cp", System.getProperty("java.class.path"), "-Drwe.home=" + ProjectFiles.root(),
                    "-Dbench.monitor.warmupSeconds=" + WARM_UP,
                    MonitorBenchmark.class.getName(), "child", server.uri().toString(), world.toString(),
                    Integer.toString(SECONDS)));
            Process child = new ProcessBuilder(command).redirectErrorStream(true).start();
            BufferedReader lines = new BufferedReader(new InputStreamReader(child.getInputStream(),
                    StandardCharsets.UTF_8));
            String line;
            while ((line = lines.readLine()) != null && !line.equals("READY")) {
                // the monitor starts
            }
            GroundTruthFeed feed = load == Load.IDLE ? null
                    : GroundTruthFeed.start(robot, "CaterpillarRobot", feedSpace, GroundTruthFeed.DEFAULT_PERIOD);
            AtomicBoolean running = new AtomicBoolean(true);
            AtomicLong calls = new AtomicLong();
            Thread control = new Thread(() -> controlLoop(laptop, load, running, calls), "control program");
            if (load != Load.IDLE) {
                control.start();
            }
            long started = System.nanoTime();
            String result = null;
            while ((line = lines.readLine()) != null) {
                if (line.startsWith("RESULT")) {
                    result = line;
                    break;
                }
                if (line.equals("STOP-LOAD")) {
                    running.set(false);
                }
            }
            running.set(false);
            control.join(5_000);
            if (feed != null) {
                feed.close();
            }
            child.waitFor(30, TimeUnit.SECONDS);
            if (result == null) {
                throw new IllegalStateException("the monitor process ended without a result");
            }
            double seconds = (System.nanoTime() - started) / 1e9;
            String[] parts = result.split(" ");
            double cpu = Double.parseDouble(parts[1]);
            long seen = Long.parseLong(parts[2]);
            double paints = Double.parseDouble(parts[3]);
            double jit = Double.parseDouble(parts[4]);
            return new double[] {cpu, calls.get() / Math.max(1, seconds - 2), seen, calls.get(), paints, jit};
        }
    }

    /** Listing 5.2's calls: forward, both front bumpers, back and turn with the lamp on a bump. */
    private static void controlLoop(XVSMRuntime laptop, Load load, AtomicBoolean running, AtomicLong calls) {
        MotorModule motor = new XVSMMotorModuleRemote(laptop, "CaterpillarRobot", "Motor-Controller");
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, "CaterpillarRobot", "Bumper-Sensor");
        X10ApplianceModule lamp = new XVSMX10ApplianceModuleRemote(laptop, "DimRoom", "Lamp");
        try {
            while (running.get()) {
                motor.setMotor(1, 0.25);
                motor.setMotor(2, 0.25);
                boolean front = bumper.getSingleBumper(6) || bumper.getSingleBumper(4);
                calls.addAndGet(front ? 3 : 4);
                if (front) {
                    motor.setMotor(1, -0.3);
                    motor.setMotor(2, -0.3);
                    lamp.on();
                    sleep(load == Load.DEMO ? 300 : 30);
                    motor.setMotor(1, 0.4);
                    motor.setMotor(2, -0.4);
                    sleep(load == Load.DEMO ? 700 : 70);
                    lamp.off();
                    calls.addAndGet(6);
                } else if (load == Load.DEMO) {
                    sleep(100);
                }
            }
        } finally {
            motor.setMotor(1, 0);
            motor.setMotor(2, 0);
            calls.addAndGet(2);
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static String javaCommand() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        sorted.sort(null);
        int n = sorted.size();
        return n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
    }

    /**
     * The monitor process: opens the window, says READY, measures, says RESULT cpuPercent answersSeen paints/s
     * jitPercent (the JIT compilers' share of the CPU percentage, from their compilation time).
     */
    static final class Child {
        static void run(String url, Path worldFile, int seconds) throws Exception {
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(worldFile));
            AtomicLong answers = new AtomicLong();
            WorldMonitor[] monitor = new WorldMonitor[1];
            try (var space = RemoteSpace.open(java.net.URI.create(url))) {
                SwingUtilities.invokeAndWait(() -> {
                    monitor[0] = new WorldMonitor(world, space, new MonitorLoader(), WorldMonitor.Windows.ONE,
                            LayoutMemory.none());
                    monitor[0].window().setBounds(0, 0, 1360, 900);
                    monitor[0].tap().add(new WorldObserver() {
                        @Override
                        public void answerSeen(AnswerSeen event) {
                            if (!event.earlier()) {
                                answers.incrementAndGet();
                            }
                        }

                        @Override
                        public void groundTruth(GroundTruth frame) {
                        }
                    });
                    monitor[0].show();
                });
                if (!monitor[0].awaitWatching(Duration.ofSeconds(30))) {
                    throw new IllegalStateException("the monitor does not watch");
                }
                System.out.println("READY");
                System.out.flush();
                var bean = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
                Thread.sleep(WARM_UP * 1000L);
                var compilation = ManagementFactory.getCompilationMXBean();
                long jitStart = compilation.getTotalCompilationTime();
                long cpuStart = bean.getProcessCpuTime();
                long wallStart = System.nanoTime();
                long paintsStart = monitor[0].window().worldView().paints();
                Thread.sleep(seconds * 1000L);
                long cpu = bean.getProcessCpuTime() - cpuStart;
                long jitMillis = compilation.getTotalCompilationTime() - jitStart;
                long wall = System.nanoTime() - wallStart;
                long paints = monitor[0].window().worldView().paints() - paintsStart;
                System.out.println("STOP-LOAD");
                System.out.flush();
                Thread.sleep(2_000); // the last answers arrive
                System.out.printf(Locale.ROOT, "RESULT %.2f %d %.2f %.2f%n", 100.0 * cpu / wall, answers.get(),
                        paints / (wall / 1e9), 100.0 * jitMillis * 1e6 / wall);
                System.out.flush();
                SwingUtilities.invokeAndWait(() -> monitor[0].close());
            }
            System.exit(0);
        }
    }
}
