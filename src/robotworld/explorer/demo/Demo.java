package robotworld.explorer.demo;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.SwingUtilities;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.FoundModule;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.description.DescriptionException;
import robotworld.description.RobotWorldAssembler;
import robotworld.explorer.FrameworkGenerator;
import robotworld.explorer.generator.GenerationListener;
import robotworld.explorer.generator.GenerationResult;
import robotworld.explorer.monitor.ConsoleMonitor;
import robotworld.explorer.monitor.MonitorLoader;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldMonitor;
import robotworld.explorer.monitor.gui.Display;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.safety.SafetyContainers;
import robotworld.safety.StopCause;
import robotworld.safety.StopRecord;
import robotworld.sim.robot.Pose;
import robotworld.sim.robot.SimModule;
import robotworld.sim.robot.SimMotorModule;
import robotworld.sim.robot.GroundTruthFeed;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.Capi;
import robotworld.space.Entry;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.server.SpaceServer;
import robotworld.description.RobotWorldDocument;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMX10ApplianceModuleRemote;

/**
 * The chapter-5 proof of concept end to end: space server, simulated robot and CM11A, exploration,
 * assembly, two generated and Ant-built frameworks, one of them with listing 5.2 in its main class, monitoring, a
 * bounded run and a summary. Every step prints what it does; a failed step ends the demo with a failed summary.
 */
public final class Demo {

    static final String ROBOT = "CaterpillarRobot";
    static final String ENVIRONMENT = "DimRoom";
    static final String PACKAGE = "chapter5demo";
    private static final Duration START_TIMEOUT = Duration.ofSeconds(60);
    /** How often the exploration step scans before it gives up on a module the simulated robot has. */
    private static final int SCANS = 3;
    private static final Pattern STATS = Pattern.compile(
            "DEMO-STATS name=(\\w+) calls=(\\d+) p50us=(\\d+) p99us=(\\d+) maxus=(\\d+)");
    private static final Pattern BUMPS = Pattern.compile("DEMO-STATS name=bumps count=(\\d+)");
    private static final int STEPS = 9;
    /** How long after its start the control program is killed with --kill-control (at most half the run). */
    private static final Duration KILL_AFTER = Duration.ofSeconds(4);
    /** The bus response timeout of the demo's programs (the simulated robot's modules): see runPrograms. */
    private static final int SIMULATOR_BUS_TIMEOUT_MS = 1_000;

    private final DemoOptions options;
    /** The safety command timeout of a clustered demo's programs: longer than a failover's pause. */
    static final int CLUSTER_COMMAND_TIMEOUT_MS = 3_000;
    /** The clustered space's members while a clustered demo runs, else null. */
    private DemoCluster cluster;
    private boolean memberKilled;
    private final PrintWriter out;
    private final DemoSummary summary = new DemoSummary();
    private int stepNumber;
    private String bumperName = "Bumper-Sensor";

    public Demo(DemoOptions options, PrintWriter out) {
        this.options = options;
        this.out = out;
    }

    /** A step's work; may throw anything, which fails the step and the demo. */
    private interface Work<T> {
        T run() throws Exception;
    }

    private <T> T step(String what, Work<T> work) throws StepFailed {
        stepNumber++;
        out.println("[" + stepNumber + "/" + STEPS + "] " + what);
        out.flush();
        long started = System.nanoTime();
        try {
            T result = work.run();
            out.printf(Locale.ROOT, "      done in %.1f s%n", (System.nanoTime() - started) / 1e9);
            out.flush();
            return result;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            summary.failures.add("step " + stepNumber + " (" + what + ") interrupted");
            throw new StepFailed();
        } catch (Exception e) {
            String message = e.getMessage() == null ? e.toString() : e.getMessage();
            if (e instanceof DescriptionException d) {
                message = d.errors().toString();
            }
            out.println("      FAILED: " + message);
            out.flush();
            summary.failures.add("step " + stepNumber + " (" + what + "): " + message);
            throw new StepFailed();
        }
    }

    private void say(String line) {
        out.println("      " + line);
        out.flush();
    }

    private static final class StepFailed extends Exception {
        private static final long serialVersionUID = 1L;

        StepFailed() {
            super(null, null, false, false);
        }
    }

    /** Runs the whole demo; never throws for a failed step, see {@link DemoSummary#succeeded()}. */
    public DemoSummary run() {
        long started = System.currentTimeMillis();
        summary.viewpoint = options.viewpoint();
        Path out = options.out().toAbsolutePath().normalize();
        List<ProgramProcess> programs = new java.util.concurrent.CopyOnWriteArrayList<>();
        // Ctrl-C or SIGTERM of the demo itself ends its programs as it would: they stop their actuators first
        Thread endPrograms = new Thread(() -> programs.forEach(ProgramProcess::close), "demo-shutdown");
        Runtime.getRuntime().addShutdownHook(endPrograms);
        try {
            Files.createDirectories(out);
            runSteps(out, programs);
        } catch (StepFailed e) {
            // reported by step()
        } catch (Exception e) {
            summary.failures.add(e.toString());
        } finally {
            for (ProgramProcess program : programs) {
                program.close();
            }
            try {
                Runtime.getRuntime().removeShutdownHook(endPrograms);
            } catch (IllegalStateException shuttingDown) {
                // the hook ends them
            }
        }
        summary.elapsedMillis = System.currentTimeMillis() - started;
        summary.print(this.out);
        return summary;
    }

    private void runSteps(Path out, List<ProgramProcess> programs) throws Exception {
        if (options.clusterMembers() > 0) {
            runStepsOnCluster(out, programs);
            return;
        }
        Path home = options.home();
        try (SpaceServer space = step("starting a space server on a free loopback port", () -> {
            SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
            say("space server at " + server.uri());
            return server;
        })) {
            String spaceUrl = space.uri().toString();
            Simulators simulators = step("starting a simulated robot (motor + bumper modules in an arena) and a "
                    + "simulated CM11A with an X10 appliance module at A3", () -> Simulators.start(home, this));
            try (simulators;
                 GroundTruthFeed groundTruth = GroundTruthFeed.start(simulators.robot, ROBOT, space.space(),
                         GroundTruthFeed.DEFAULT_PERIOD)) {
                say("the robot's ground truth goes to " + groundTruth.containerName() + " for the monitor's world "
                        + "view");
                runWithSimulators(out, programs, spaceUrl, simulators);
            }
        }
    }

    /** The same steps with the space on a cluster of member processes, one of which is killed mid-run. */
    private void runStepsOnCluster(Path out, List<ProgramProcess> programs) throws Exception {
        Path home = options.home();
        java.nio.file.Files.createDirectories(out);
        try (DemoCluster members = step("starting " + options.clusterMembers() + " clustered space servers (rwe space"
                + " --cluster), each its own process", () -> DemoCluster.start(options.clusterMembers(), out))) {
            cluster = members;
            String spaceUrl = members.spaceUrl();
            say("space servers at " + spaceUrl + " (member logs in " + out + ")");
            Simulators simulators = step("starting a simulated robot (motor + bumper modules in an arena) and a "
                    + "simulated CM11A with an X10 appliance module at A3", () -> Simulators.start(home, this));
            try (simulators;
                 Capi feedSpace = MonitorSpace.open(spaceUrl);
                 GroundTruthFeed groundTruth = GroundTruthFeed.start(simulators.robot, ROBOT, feedSpace,
                         GroundTruthFeed.DEFAULT_PERIOD)) {
                say("the robot's ground truth goes to " + groundTruth.containerName() + " for the monitor's world "
                        + "view");
                runWithSimulators(out, programs, spaceUrl, simulators);
            } finally {
                cluster = null;
            }
        }
    }

    /**
     * Kills the first space server (the one every program talks to first) once, halfway through the run; returns
     * what the world looked like then (null when nothing was killed now).
     */
    private MemberKillMark killMemberHalfway(long until, Simulators sims, int bumpsSoFar)
            throws InterruptedException {
        if (cluster == null || memberKilled) {
            return null;
        }
        if (System.currentTimeMillis() >= until - options.run().toMillis() / 2) {
            memberKilled = true;
            MemberKillMark mark = new MemberKillMark(cluster.url(0), sims.robot.pose(), bumpsSoFar,
                    sims.on.get() + sims.off.get());
            long pid = cluster.kill(0);
            say("killed the space server " + mark.url + " (pid " + pid + ", SIGKILL) while the robot drives;"
                    + " the programs go on with the other members");
            return mark;
        }
        return null;
    }

    /** The world when a member was killed, to tell what happened after. */
    private record MemberKillMark(String url, Pose pose, int bumps, int switches) {
    }

    /** The two simulators and their ports. */
    private static final class Simulators implements AutoCloseable {
        SimulatedRobot robot;
        SimulatedCm11a cm11a;
        String busPort;
        String x10Port;
        final AtomicInteger on = new AtomicInteger();
        final AtomicInteger off = new AtomicInteger();

        static Simulators start(Path home, Demo demo) throws Exception {
            Simulators s = new Simulators();
            try {
                Path sim = home.resolve("docs/examples/demo-robot.sim");
                s.robot = SimulatedRobot.load(sim);
                s.busPort = s.robot.serve("tcp://127.0.0.1:0");
                demo.say("robot from " + sim + " on " + s.busPort + ", at " + s.robot.pose());
                s.cm11a = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A3=appliance");
                s.cm11a.onPowerLine(frame -> {
                    if (frame.equals("A On")) {
                        s.on.incrementAndGet();
                    } else if (frame.equals("A Off")) {
                        s.off.incrementAndGet();
                    }
                });
                s.x10Port = s.cm11a.listen(0);
                demo.say("CM11A on " + s.x10Port + " with an appliance module (the lamp) at A3");
                return s;
            } catch (Exception e) {
                s.close();
                throw e;
            }
        }

        @Override
        public void close() {
            if (robot != null) {
                robot.close();
            }
            if (cm11a != null) {
                cm11a.close();
            }
        }
    }

    private void runWithSimulators(Path out, List<ProgramProcess> programs, String spaceUrl, Simulators sims)
            throws Exception {
        Path home = options.home();
        summary.robotDescription = out.resolve("descriptions/" + ROBOT + ".xml");
        step("exploring the simulated robot's bus and writing its robot description", () -> {
            try (RS485Bus bus = new RS485Bus(sims.busPort, SerialSettings.eightNoneOne(115200),
                    BusTiming.defaults())) {
                RobotExplorer explorer = new RobotExplorer(bus, new ModuleCatalog(home.resolve("ModuleDescriptions")))
                        .host("robot-laptop");
                // the whole address range, as a user's exploration does (about 3 s at 115200 baud). The demo knows
                // which modules its simulated robot has: a scan that missed one (a busy machine can hold a
                // simulated module's reply up past every window) is repeated, as a user would, and said so
                Set<Integer> present = new TreeSet<>();
                sims.robot.config().modules().forEach(module -> present.add(module.common().address()));
                ExplorationResult result;
                Set<Integer> missed;
                int scan = 0;
                do {
                    scan++;
                    say("scanning addresses 1..247 of " + sims.busPort + (scan > 1 ? " again (scan " + scan + " of "
                            + SCANS + ")" : ""));
                    result = explorer.explore(ROBOT, new ExplorationListener() {
                        @Override
                        public void moduleFound(FoundModule module) {
                            say("found " + module);
                            if (module.moduleClass().contains("Bumper")) {
                                bumperName = module.name();
                            }
                        }
                    });
                    missed = new TreeSet<>(present);
                    for (FoundModule module : result.modules()) {
                        missed.remove(module.address());
                    }
                    if (!missed.isEmpty()) {
                        say("the scan missed the simulated robot's module(s) at address(es) " + missed + " ("
                                + result.statistics() + ")");
                    }
                } while (!missed.isEmpty() && scan < SCANS);
                if (!missed.isEmpty()) {
                    throw new IllegalStateException("after " + SCANS + " scans, the simulated robot's module(s) at "
                            + "address(es) " + missed + " still did not answer");
                }
                if (result.description().isEmpty()) {
                    throw new IllegalStateException("no module found on the simulated robot's bus");
                }
                RobotWorldAssembler.write(result.description().get(), summary.robotDescription);
                say("wrote " + summary.robotDescription);
            }
            return null;
        });

        summary.world = out.resolve("descriptions/Chapter5Demo-world.xml");
        Path environmentFile = home.resolve("docs/examples/parts/dim-room.xml");
        RobotWorldDocument world = step("assembling the RobotWorld from the robot description and the hand-written "
                + "environment description " + environmentFile, () -> {
            RobotWorldDocument document = new RobotWorldAssembler("Chapter5Demo").packageName(PACKAGE)
                    .spaceUrl(spaceUrl).addRobot(summary.robotDescription).addEnvironment(environmentFile).assemble();
            RobotWorldAssembler.write(document, summary.world);
            say("wrote " + summary.world + " (package " + PACKAGE + ", space " + spaceUrl + ")");
            return document;
        });

        boolean robotControls = options.viewpoint() == Viewpoint.ROBOT;
        summary.robotProject = out.resolve("robot");
        summary.environmentProject = out.resolve("environment");
        GenerationResult[] generated = new GenerationResult[2];
        step("generating the robot and the environment viewpoint frameworks, listing 5.2 into the "
                + (robotControls ? ROBOT : ENVIRONMENT) + " main class, building each with its own build.xml ("
                + AntBuild.antCommand() + " compile)", () -> {
            FrameworkGenerator generator = new FrameworkGenerator();
            generated[0] = generator.generate(summary.world, ROBOT, null, summary.robotProject, true,
                    GenerationListener.SILENT);
            generated[1] = generator.generate(summary.world, ENVIRONMENT, null, summary.environmentProject, true,
                    GenerationListener.SILENT);
            GenerationResult control = robotControls ? generated[0] : generated[1];
            Path mainSource = control.destination().resolve("src/" + control.mainClass().replace('.', '/')
                    + ".java");
            ControlProgram.insert(mainSource);
            say("control program inserted into " + mainSource);
            for (GenerationResult result : generated) {
                AntBuild.compile(result.destination());
                say("built " + result.destination() + " (main class " + result.mainClass() + ")");
            }
            return null;
        });

        MonitoredWorld monitored = MonitoredWorld.of(world);
        DemoRecording recording = null;
        if (options.record() != null) {
            recording = DemoRecording.start(options.record(), monitored, summary.world, spaceUrl);
            say("recording the world's traffic (and the robot's ground truth) into " + options.record());
        }
        try {
            monitorAndRun(monitored, programs, spaceUrl, sims, generated, robotControls);
        } finally {
            if (recording != null) {
                say(recording.close());
            }
        }
        step("checking the outcome", () -> {
            List<String> problems = new ArrayList<>();
            if (summary.distanceMoved() < 20) {
                problems.add("the robot did not move");
            }
            if (options.killControl()) {
                if (summary.kill == null || summary.kill.millisToZero() < 0) {
                    problems.add("the robot did not stop after its control program was killed");
                }
            } else if (summary.bumps < 1) {
                problems.add("no bump happened");
            }
            if (!options.killControl() && (summary.lampOnFrames < 1 || summary.lampOffFrames < 1)) {
                problems.add("the lamp was not switched on and off at the CM11A");
            }
            if (options.clusterMembers() > 0 && !options.killControl()) {
                if (summary.memberKill == null) {
                    problems.add("no space server was killed (the run ended before its halfway point)");
                } else if (summary.memberKill.distanceAfter() < 20 && summary.memberKill.bumpsAfter() < 1) {
                    problems.add("the robot neither moved nor bumped after the space server was killed");
                }
            }
            if (summary.monitorAnswers < 1) {
                problems.add("the monitor received nothing");
            }
            if (!problems.isEmpty()) {
                throw new IllegalStateException(String.join("; ", problems));
            }
            say(options.killControl() ? "robot moved, stopped by itself when its control program was killed, monitor "
                    + "saw it" : "robot moved, bumped, lamp switched, monitor saw it");
            return null;
        });
    }

    /** Monitors the world (console tally, and windows on a desktop) while the programs run. */
    private void monitorAndRun(MonitoredWorld monitored, List<ProgramProcess> programs, String spaceUrl,
            Simulators sims, GenerationResult[] generated, boolean robotControls) throws Exception {
        boolean windows = !options.console() && Display.usable();
        if (!options.console() && !windows) {
            say("no monitor window: " + Display.problem() + "; the console monitor shows the run instead");
        }
        MonitorTally tally = new MonitorTally(windows ? null : out());
        try (Capi monitorSpace = MonitorSpace.open(spaceUrl)) {
            ConsoleMonitor console = step("monitoring all " + monitored.moduleCount() + " modules: "
                    + (windows ? "monitor windows (and a silent tally)" : "console monitor (changes shown below)"),
                    () -> new ConsoleMonitor(monitored, monitorSpace, new PrintWriter(tally, true)));
            WorldMonitor[] worldMonitor = new WorldMonitor[1];
            try (console) {
                if (windows) {
                    try {
                        SwingUtilities.invokeAndWait(() -> {
                            worldMonitor[0] = new WorldMonitor(monitored, monitorSpace, new MonitorLoader(),
                                    WorldMonitor.Windows.ONE, LayoutMemory.fromSettings());
                            worldMonitor[0].show();
                        });
                    } catch (java.lang.reflect.InvocationTargetException | Error e) {
                        Throwable cause = e instanceof java.lang.reflect.InvocationTargetException i ? i.getCause() : e;
                        say("no monitor window (" + cause + "); the console monitor shows the run instead");
                        tally.echoTo(out());
                    }
                }
                runPrograms(programs, spaceUrl, sims, generated, robotControls);
                checkSafeState(programs, sims, monitorSpace);
            } finally {
                if (worldMonitor[0] != null) {
                    SwingUtilities.invokeAndWait(() -> worldMonitor[0].close());
                }
                Thread.sleep(300); // the last answers reach the monitor
                summary.monitorAnswers = tally.answers.get();
                summary.monitorBumps = tally.bumpAnswers.get();
                summary.monitorLampOn = tally.lampOn.get();
                summary.monitorLampOff = tally.lampOff.get();
                summary.monitorMotor = tally.motorAnswers.get();
                summary.monitorStops = tally.stops.get();
                summary.endPose = sims.robot.pose();
            }
        }
    }

    private PrintWriter out() {
        return out;
    }

    private void runPrograms(List<ProgramProcess> programs, String spaceUrl, Simulators sims,
            GenerationResult[] generated, boolean robotControls) throws Exception {
        GenerationResult provider = robotControls ? generated[1] : generated[0];
        GenerationResult controller = robotControls ? generated[0] : generated[1];
        List<String> properties = new ArrayList<>(List.of("-Drwe.space.url=" + spaceUrl,
                "-Drwe.port." + ROBOT + ".bus=" + sims.busPort, "-Drwe.port." + ENVIRONMENT + ".x10=" + sims.x10Port,
                "-Drwe.call.timeout.ms=" + START_TIMEOUT.toMillis()));
        // the robot is a simulator in another program, not a module on a serial line: on a busy machine it can take
        // longer than a real module's 100 ms to answer, and the demo must not fail for that
        properties.add("-D" + BusTiming.RESPONSE_TIMEOUT_PROPERTY + "="
                + System.getProperty(BusTiming.RESPONSE_TIMEOUT_PROPERTY, String.valueOf(SIMULATOR_BUS_TIMEOUT_MS)));
        properties.addAll(safetySettings());
        if (options.clusterMembers() > 0 && System.getProperty("rwe.command.timeout.ms") == null) {
            // a member's failure pauses calls for up to a second or two: longer than the default command timeout,
            // which would stop the actuators (safely) at every failover
            properties.add("-Drwe.command.timeout.ms=" + CLUSTER_COMMAND_TIMEOUT_MS);
        }
        step("running " + provider.mainClass() + " unchanged as the resource provider, then " + controller.mainClass()
                + " with the control program for " + options.run().toSeconds() + " s", () -> {
            ProgramProcess providing = ProgramProcess.start(provider.destination(), provider.mainClass(), properties);
            programs.add(providing);
            say("provider " + provider.mainClass() + " started (pid " + providing.pid() + ", log "
                    + providing.log() + ")");
            awaitProvider(spaceUrl, robotControls, providing);
            sims.on.set(0);
            sims.off.set(0);
            summary.startPose = sims.robot.pose();
            long until = System.currentTimeMillis() + options.run().toMillis();
            List<String> controlProperties = new ArrayList<>(properties);
            controlProperties.add("-D" + ControlProgram.UNTIL_PROPERTY + "=" + until);
            ProgramProcess controlling = ProgramProcess.start(controller.destination(), controller.mainClass(),
                    controlProperties);
            programs.add(controlling);
            say("control program " + controller.mainClass() + " started (pid " + controlling.pid() + ", log "
                    + controlling.log() + ")" + (options.killControl() ? ", to be killed while the robot drives"
                    : ", runs until the deadline"));
            if (options.killControl()) {
                killMidDrive(controlling, sims, robotControls, until);
                return null;
            }
            int reported = 0;
            MemberKillMark memberKill = null;
            while (System.currentTimeMillis() < until + 20_000 && controlling.isAlive()
                    && !controlling.output().contains("DEMO-END")) {
                Thread.sleep(200);
                MemberKillMark killedNow = killMemberHalfway(until, sims, reported);
                memberKill = killedNow != null ? killedNow : memberKill;
                long bumps = controlling.output().lines().filter(l -> l.startsWith("DEMO-BUMP")).count();
                if (bumps > reported) {
                    reported = (int) bumps;
                    say("bump #" + bumps + " at " + sims.robot.pose() + "; lamp switches so far: " + sims.on.get()
                            + " on, " + sims.off.get() + " off");
                }
            }
            summary.lampOnFrames = sims.on.get();
            summary.lampOffFrames = sims.off.get();
            String output = controlling.output();
            if (memberKill != null) {
                int bumpsAtEnd = (int) output.lines().filter(l -> l.startsWith("DEMO-BUMP")).count();
                summary.memberKill = new DemoSummary.MemberKill(memberKill.url(), memberKill.pose(),
                        bumpsAtEnd - memberKill.bumps(), sims.on.get() + sims.off.get() - memberKill.switches(),
                        sims.robot.pose());
            }
            readStatistics(output);
            if (output.contains("DEMO-FAILED")) {
                throw new IllegalStateException("the control program failed; its log:\n" + controlling.tail(20));
            }
            if (!output.contains("DEMO-END")) {
                throw new IllegalStateException("the control program did not finish in time; its log:\n"
                        + controlling.tail(20));
            }
            if (!providing.isAlive()) {
                throw new IllegalStateException("the provider ended early; its log:\n" + providing.tail(20));
            }
            return null;
        });
    }

    /**
     * Kills the control program (SIGKILL) once the robot has driven forward for a while, then watches the motor
     * module until it reads 0 and the robot has come to rest.
     */
    private void killMidDrive(ProgramProcess controlling, Simulators sims, boolean robotControls, long until)
            throws Exception {
        SimMotorModule motors = wheelMotors(sims.robot);
        long killAt = System.currentTimeMillis() + Math.min(KILL_AFTER.toMillis(), options.run().toMillis() / 2);
        while (System.currentTimeMillis() < Math.max(killAt, until) + 20_000 && controlling.isAlive()) {
            boolean forward = motors.setSpeed(1) > 0 && motors.setSpeed(2) > 0;
            if (System.currentTimeMillis() >= killAt && forward) {
                break;
            }
            Thread.sleep(5);
        }
        if (!controlling.isAlive()) {
            throw new IllegalStateException("the control program ended before it could be killed; its log:\n"
                    + controlling.tail(20));
        }
        int left = motors.setSpeed(1);
        int right = motors.setSpeed(2);
        Pose atKill = sims.robot.pose();
        long killed = System.nanoTime();
        controlling.kill();
        say(String.format(Locale.ROOT, "KILLED the control program %s (SIGKILL, pid %d) while the robot drove at "
                + "%+.3f/%+.3f at %s", controlling.mainClass(), controlling.pid(), left / 1000.0, right / 1000.0,
                atKill));
        long stoppedAt = -1;
        long nextReport = 0;
        while (System.nanoTime() - killed < Duration.ofSeconds(10).toNanos()) {
            long now = System.nanoTime();
            boolean stopped = motors.setSpeed(1) == 0 && motors.setSpeed(2) == 0;
            if (stopped) {
                stoppedAt = now;
                break;
            }
            if (now >= nextReport) {
                say(String.format(Locale.ROOT, "  %4d ms after the kill: motors %+.3f/%+.3f, robot at %s",
                        (now - killed) / 1_000_000, motors.setSpeed(1) / 1000.0, motors.setSpeed(2) / 1000.0,
                        sims.robot.pose()));
                nextReport = now + 100_000_000L;
            }
            Thread.sleep(1);
        }
        double millis = stoppedAt < 0 ? -1 : (stoppedAt - killed) / 1e6;
        Pose rest = awaitRest(sims.robot);
        String why = robotControls
                ? "the motor module's own bus watchdog (" + wheelMotorsWatchdog(motors) + " ms without a frame from its "
                        + "master: the killed program served it)"
                : "the robot's program, which serves the motors: their commander went silent for the command timeout";
        summary.kill = new DemoSummary.Kill(controlling.mainClass(), left, right, atKill, millis, rest,
                stoppedAt < 0 ? "nobody: the motors still run" : why);
        if (stoppedAt < 0) {
            throw new IllegalStateException("the motors still run 10 s after the control program was killed");
        }
        say(String.format(Locale.ROOT, "  motors read 0 at the module %.0f ms after the kill, stopped by %s", millis,
                why));
        say(String.format(Locale.ROOT, "  the robot came to rest at %s, %.0f mm after the kill", rest,
                atKill.distanceTo(rest)));
    }

    /** The motor module that drives the simulated robot's wheels. */
    private static SimMotorModule wheelMotors(SimulatedRobot robot) {
        for (SimModule module : robot.simulation().modules().values()) {
            if (module instanceof SimMotorModule motors && motors.drivesWheels()) {
                return motors;
            }
        }
        throw new IllegalStateException("the simulated robot has no motor module driving its wheels");
    }

    private static int wheelMotorsWatchdog(SimMotorModule motors) {
        return motors.watchdogMillis();
    }

    /** Waits until the simulated robot stands still (its pose unchanged for 200 ms), at most 5 s. */
    private static Pose awaitRest(SimulatedRobot robot) throws InterruptedException {
        Pose last = robot.pose();
        long stillSince = System.nanoTime();
        long deadline = System.nanoTime() + Duration.ofSeconds(5).toNanos();
        while (System.nanoTime() < deadline) {
            Thread.sleep(20);
            Pose now = robot.pose();
            if (now.distanceTo(last) > 0.01) {
                last = now;
                stillSince = System.nanoTime();
            } else if (System.nanoTime() - stillSince > 200_000_000L) {
                break;
            }
        }
        return last;
    }

    /**
     * Ends the programs as Ctrl-C would (SIGTERM: their runtimes stop their actuators first), then reads the
     * actuators at the simulated hardware and the stop records of the space.
     */
    private void checkSafeState(List<ProgramProcess> programs, Simulators sims, Capi space) throws StepFailed {
        step("ending the programs (SIGTERM, as Ctrl-C) and checking that the robot's actuators are in their safe "
                + "state", () -> {
            for (ProgramProcess program : programs) {
                if (program.isAlive()) {
                    program.close();
                    say("ended " + program.mainClass() + " (SIGTERM)");
                }
            }
            List<String> moving = new ArrayList<>();
            for (SimModule module : sims.robot.simulation().modules().values()) {
                if (module instanceof SimMotorModule motors) {
                    List<Integer> speeds = new ArrayList<>();
                    for (int motor = 1; motor <= SimMotorModule.CHANNELS; motor++) {
                        speeds.add(motors.setSpeed(motor));
                    }
                    String line = ROBOT + " motor module at bus address " + module.address() + ": motors 1-8 read "
                            + speeds + (speeds.stream().allMatch(v -> v == 0) ? ": safe (0)" : ": STILL MOVING")
                            + (motors.watchdogMillis() > 0 ? ", bus watchdog armed with " + motors.watchdogMillis()
                            + " ms" : "");
                    summary.safeState.add(line);
                    say(line);
                    if (speeds.stream().anyMatch(v -> v != 0)) {
                        moving.add("motor module " + module.address());
                    }
                }
            }
            String lamp = ENVIRONMENT + " lamp (X10 A3): " + (sims.cm11a.appliance(robotworld.x10.X10Address.of('A', 3))
                    .isOn() ? "on" : "off") + ", left as it is (X10 safe state: unchanged)";
            summary.safeState.add(lamp);
            say(lamp);
            for (Entry entry : space.read(SafetyContainers.stops(space), Timeout.TRY_ONCE,
                    Selector.fifo(Selector.ALL))) {
                StopRecord stop = StopRecord.parse(entry);
                summary.stops.add(stop.toString());
                say("stop record: " + stop);
            }
            if (!moving.isEmpty()) {
                throw new IllegalStateException("not in their safe state after the programs ended: " + moving);
            }
            summary.safe = true;
            return null;
        });
    }

    /** The safety settings given to the demo itself ({@code -Drwe.command.timeout.ms=...}), for its programs too. */
    private static List<String> safetySettings() {
        List<String> settings = new ArrayList<>();
        for (String key : System.getProperties().stringPropertyNames()) {
            if (key.startsWith("rwe.command.timeout.ms") || key.startsWith("rwe.watchdog.ms")
                    || key.startsWith("rwe.x10.safe.state") || key.equals("rwe.heartbeat.ms")) {
                settings.add("-D" + key + "=" + System.getProperty(key));
            }
        }
        return settings;
    }

    /** Waits until the provider serves: a first call through the space that waits for its answer. */
    private void awaitProvider(String spaceUrl, boolean robotControls, ProgramProcess providing) throws Exception {
        try (XVSMRuntime probe = XVSMRuntime.connect(spaceUrl, "demo-monitor")) {
            if (robotControls) {
                XVSMX10ApplianceModuleRemote lamp = probe.own(new XVSMX10ApplianceModuleRemote(probe, ENVIRONMENT,
                        "Lamp"));
                lamp.setCallTimeout(START_TIMEOUT);
                lamp.off();
            } else {
                XVSMBumperModuleRemote bumper = probe.own(new XVSMBumperModuleRemote(probe, ROBOT, bumperName));
                bumper.setCallTimeout(START_TIMEOUT);
                bumper.getAllBumper();
            }
            say("provider answers through the space");
        } catch (RuntimeException e) {
            throw new IllegalStateException("the provider did not answer: " + e.getMessage() + "; its log:\n"
                    + providing.tail(20), e);
        }
    }

    private void readStatistics(String output) {
        Matcher matcher = STATS.matcher(output);
        while (matcher.find()) {
            summary.calls.add(new DemoSummary.CallStats(matcher.group(1), Integer.parseInt(matcher.group(2)),
                    Long.parseLong(matcher.group(3)), Long.parseLong(matcher.group(4)),
                    Long.parseLong(matcher.group(5))));
        }
        Matcher bumps = BUMPS.matcher(output);
        if (bumps.find()) {
            summary.bumps = Integer.parseInt(bumps.group(1));
        }
    }
}
