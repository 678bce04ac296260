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
        try (SimulatedRobot robot = SimulatedRobot.create(chosen)) {
            String served;
            try {
                served = robot.serve(port);
            } catch (InvalidPortNameException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
            out.println(robot.describe());
            out.println("serving the bus on " + served);
            out.println(seconds == null ? "press Ctrl-C to stop" : "stopping after " + seconds + " s");
            out.flush();
            CountDownLatch stopped = new CountDownLatch(1);
            Thread hook = new Thread(stopped::countDown);
            Runtime.getRuntime().addShutdownHook(hook);
            try {
                if (seconds == null) {
                    stopped.await();
                } else {
                    stopped.await(Math.round(seconds * 1000), TimeUnit.MILLISECONDS);
                }
            } finally {
                try {
                    Runtime.getRuntime().removeShutdownHook(hook);
                } catch (IllegalStateException e) {
                    // shutting down already
                }
            }
            out.println("robot at " + robot.pose());
            return 0;
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
