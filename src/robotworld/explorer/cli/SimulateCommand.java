package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robotworld.sim.Cm11aSimulatorRunner;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.control.Cm11aControl;
import robotworld.sim.control.ControlChannel;

/** {@code rwe simulate DEVICE ...}: runs a simulated device until stopped with Ctrl-C. */
@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = "Run a simulated device that real drivers can talk to; stop it with Ctrl-C.",
        subcommands = {SimulateCommand.Cm11a.class, SimulateRobotCommand.class})
public final class SimulateCommand implements Runnable {

    @Spec
    private CommandSpec spec;

    @Override
    public void run() {
        throw new ParameterException(spec.commandLine(), "name the device to simulate: cm11a or robot");
    }

    /** Timing choices on the command line. */
    enum Timing { real, fast }

    /** {@code rwe simulate cm11a --port tcp://127.0.0.1:PORT [--devices A1=lamp,A3=appliance] [--timing ...]}. */
    @Command(name = "cm11a", mixinStandardHelpOptions = true,
            description = {"Simulate a CM11A X10 computer interface with lamp and appliance modules.",
                    "It answers the CM11A serial protocol like the real interface and prints what goes out "
                            + "on the power line."})
    static final class Cm11a implements Callable<Integer> {

        @Option(names = "--port", required = true, paramLabel = "PORT",
                description = "tcp://127.0.0.1:PORT to listen on (loopback only; 0 picks a free port), "
                        + "or a serial device such as one end of a socat pty pair")
        private String port;

        @Option(names = "--devices", paramLabel = "LIST", defaultValue = "A1=lamp,A3=appliance",
                description = "modules on the power line, ADDRESS=lamp|appliance, comma-separated "
                        + "(default: ${DEFAULT-VALUE})")
        private String devices;

        @Option(names = "--timing", paramLabel = "real|fast", defaultValue = "real",
                description = "real: 4800 baud pacing and power-line time; fast: no delays (default: ${DEFAULT-VALUE})")
        private Timing timing;

        @Option(names = "--power-line-ms", paramLabel = "MS", defaultValue = "500",
                description = "power-line time of one X10 frame with real timing (default: ${DEFAULT-VALUE})")
        private int powerLineMillis;

        @Option(names = "--power-fail", description = "start as after a power failure: poll 0xA5 until the clock is set")
        private boolean powerFail;

        @Option(names = "--control", paramLabel = "stdin|tcp://127.0.0.1:PORT",
                description = "a control channel to inject power-line traffic and faults (see docs/x10.md)")
        private String control;

        @Spec
        private CommandSpec spec;

        @Override
        public Integer call() throws Exception {
            if (powerLineMillis < 0) {
                throw new ParameterException(spec.commandLine(), "--power-line-ms must be 0 or more");
            }
            Cm11aTiming chosen = timing == Timing.fast ? Cm11aTiming.fast()
                    : Cm11aTiming.real(Duration.ofMillis(powerLineMillis));
            PrintWriter out = spec.commandLine().getOut();
            Cm11aSimulatorRunner.Started started;
            try {
                started = Cm11aSimulatorRunner.start(port, devices, chosen, powerFail);
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
            CountDownLatch stopped = new CountDownLatch(1);
            Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                started.sim().close();
                stopped.countDown();
            }));
            started.sim().onPowerLine(transmission -> {
                out.println("power line: " + transmission);
                out.flush();
            });
            out.println(started.describe());
            if (control != null) {
                try {
                    out.println("control channel on " + ControlChannel.open(control, new Cm11aControl(started.sim()))
                            .where() + " (help lists the commands)");
                } catch (IllegalArgumentException e) {
                    started.sim().close();
                    throw new ParameterException(spec.commandLine(), "--control: " + e.getMessage());
                }
            }
            out.println("press Ctrl-C to stop");
            out.flush();
            stopped.await();
            return 0;
        }
    }
}
