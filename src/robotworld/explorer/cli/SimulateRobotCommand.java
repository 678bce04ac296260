package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robotworld.bus.InvalidPortNameException;
import robotworld.core.RuntimeSettings;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.sim.robot.GroundTruthFeed;
import robotworld.space.Capi;
import robotworld.sim.control.ControlChannel;
import robotworld.sim.control.RobotControl;
import robotworld.sim.robot.LineTiming;
import robotworld.sim.robot.SimRobotConfig;
import robotworld.sim.robot.SimRobotConfigException;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;

/** {@code rwe simulate robot --config F --port tcp://...}: a simulated robot whose bus modules answer Modbus RTU. */
@Command(name = "robot", mixinStandardHelpOptions = true,
        description = {"Simulate a robot: Modbus RTU bus modules (motor, servo, bumper, IR distance) in a 2-D world.",
                "Motor speeds drive the robot, bumpers close on contact, IR sensors measure distances.",
                "The configuration format is described in docs/bus.md; see docs/examples/simulated-robot.sim."})
final class SimulateRobotCommand implements Callable<Integer> {

    private static final long STATUS_NANOS = 1_000_000_000L;

    @Option(names = "--config", required = true, paramLabel = "FILE", description = "the robot's configuration (XML)")
    private Path config;

    @Option(names = "--port", defaultValue = "tcp://127.0.0.1:5020", paramLabel = "PORT",
            description = "tcp://HOST:PORT to listen on (0 picks a free port; default ${DEFAULT-VALUE}), or a "
                    + "serial device such as one end of a socat pty pair")
    private String port;

    @Option(names = "--timing", paramLabel = "fast|real",
            description = "override the configuration: fast replies at once, real paces them at the baud rate")
    private String timing;

    @Option(names = "--baud", paramLabel = "BAUD", description = "override the configured baud rate")
    private Integer baud;

    @Option(names = "--time-scale", paramLabel = "X", description = "override the world's simulated seconds per second")
    private Double timeScale;

    @Option(names = "--for", paramLabel = "SECONDS", description = "stop after this long (default: run until Ctrl-C)")
    private Double seconds;

    @Option(names = "--space", paramLabel = "URL[,URL...]",
            description = "publish the robot's ground truth (pose, rays, contacts, speeds) to this space server (or "
                    + "a clustered space's servers, separated by commas) for the monitor's world view (default: rwe.space.url or RWE_SPACE_URL if set, else none)")
    private String spaceUrl;

    @Option(names = "--participant", paramLabel = "NAME",
            description = "the robot's name in the world, naming the container <NAME>GROUNDTRUTH (default: the "
                    + "configuration's name)")
    private String participant;

    @Option(names = {"-q", "--quiet"}, description = "no status line every second")
    private boolean quiet;

    @Option(names = "--control", paramLabel = "stdin|tcp://127.0.0.1:PORT",
            description = "a control channel to move the robot, push obstacles, fail or slow modules (see docs/bus.md)")
    private String control;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        SimRobotConfig chosen;
        try {
            chosen = overridden(SimRobotConfigReader.read(config));
        } catch (SimRobotConfigException e) {
            for (String problem : e.problems()) {
                spec.commandLine().getErr().println(problem);
            }
            return 1;
        }
        String url = spaceUrl != null ? spaceUrl : spaceOverride();
        try (SimulatedRobot robot = SimulatedRobot.create(chosen);
             Capi space = url == null ? null : openSpace(url)) {
            String served;
            try {
                served = robot.serve(port);
            } catch (InvalidPortNameException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
            out.println(robot.describe());
            out.println("serving the bus on " + served);
            if (control != null) {
                try {
                    out.println("control channel on " + ControlChannel.open(control, new RobotControl(robot)).where()
                            + " (help lists the commands)");
                } catch (IllegalArgumentException e) {
                    throw new ParameterException(spec.commandLine(), "--control: " + e.getMessage());
                }
            }
            String name = participant != null ? participant : chosen.name();
            try (GroundTruthFeed feed = GroundTruthFeed.start(robot, name, space, GroundTruthFeed.DEFAULT_PERIOD)) {
                if (space != null) {
                    out.println("publishing its ground truth to " + url + " as " + feed.containerName()
                            + " (20 frames/s)");
                }
                out.println(seconds == null ? "press Ctrl-C to stop" : "stopping after " + seconds + " s");
                out.flush();
                runUntilStopped(feed, out);
            }
            out.println("robot at " + robot.pose());
            return 0;
        }
    }

    /** Until Ctrl-C or --for, with a status line every second unless --quiet. */
    private void runUntilStopped(GroundTruthFeed feed, PrintWriter out) throws InterruptedException {
        CountDownLatch stopped = new CountDownLatch(1);
        Thread hook = new Thread(stopped::countDown);
        Runtime.getRuntime().addShutdownHook(hook);
        long started = System.nanoTime();
        long end = seconds == null ? Long.MAX_VALUE : started + Math.round(seconds * 1e9);
        try {
            while (true) {
                long now = System.nanoTime();
                long wait = Math.min(STATUS_NANOS - (now - started) % STATUS_NANOS, end - now);
                if (wait <= 0 || stopped.await(wait, TimeUnit.NANOSECONDS)) {
                    return;
                }
                if (!quiet && System.nanoTime() < end) {
                    out.println(SimulationStatus.line(System.nanoTime() - started, feed));
                    out.flush();
                }
            }
        } catch (InterruptedException e) {
            // stopped from inside the JVM (tests, embedding): end as --for would
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException e) {
                // shutting down already
            }
        }
    }

    /** {@code rwe.space.url} / {@code RWE_SPACE_URL}, or null: a simulator publishes only when told where. */
    private static String spaceOverride() {
        try {
            return RuntimeSettings.fromSystem().spaceUrl(null);
        } catch (IllegalStateException none) {
            return null;
        }
    }

    private Capi openSpace(String url) {
        try {
            return MonitorSpace.open(url);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "--space: " + e.getMessage());
        }
    }

    private SimRobotConfig overridden(SimRobotConfig read) {
        SimRobotConfig result = read;
        try {
            if (timing != null) {
                result = result.withTiming(LineTiming.parse(timing));
            }
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "--timing: " + e.getMessage());
        }
        if (baud != null) {
            if (baud < 300 || baud > 4_000_000) {
                throw new ParameterException(spec.commandLine(), "--baud must be 300..4000000");
            }
            result = result.withBaud(baud);
        }
        if (timeScale != null) {
            if (!(timeScale > 0 && timeScale <= 1000)) {
                throw new ParameterException(spec.commandLine(), "--time-scale must be in (0, 1000]");
            }
            result = result.withTimeScale(timeScale);
        }
        if (seconds != null && !(seconds > 0)) {
            throw new ParameterException(spec.commandLine(), "--for must be positive");
        }
        return result;
    }
}
