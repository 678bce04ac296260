package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robotworld.explorer.demo.Demo;
import robotworld.explorer.demo.DemoOptions;
import robotworld.explorer.demo.DemoSummary;
import robotworld.explorer.demo.Viewpoint;

/**
 * {@code rwe demo [--seconds N] [--viewpoint robot|environment] [--out DIR] [--console] [--kill-control]}: the
 * chapter-5 demo.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = {"Run the thesis chapter-5 scenario end to end on simulated hardware (see docs/demo.md):",
                "space server, simulated robot and CM11A, bus exploration, world assembly, two generated frameworks",
                "built with plain Ant, listing 5.2 as the control program, monitoring, and a summary.",
                "Exit code 0 when every step worked, 1 when one failed."})
final class DemoCommand implements Callable<Integer> {

    @Option(names = "--seconds", paramLabel = "N", defaultValue = "30",
            description = "how long the control program runs (default: ${DEFAULT-VALUE})")
    private double seconds;

    @Option(names = "--viewpoint", paramLabel = "robot|environment", defaultValue = "robot",
            description = "whose main class gets the control program (default: ${DEFAULT-VALUE}); "
                    + "environment: DimRoom drives the robot remotely (thesis 5.3)")
    private String viewpoint;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "build/demo",
            description = "where the descriptions and generated projects go (default: ${DEFAULT-VALUE})")
    private Path out;

    @Option(names = "--console", description = "console monitor even when a display is available")
    private boolean console;

    @Option(names = "--kill-control", description = "kill the control program (SIGKILL) while the robot drives "
            + "and show the robot stopping by itself (docs/safety.md)")
    private boolean killControl;

    @Option(names = "--record", paramLabel = "FILE.mcap",
            description = "record the world's traffic into FILE.mcap (see docs/recording.md)")
    private Path record;

    @Option(names = "--cluster", paramLabel = "N", defaultValue = "0",
            description = "run the space as a cluster of N server processes (3 to 5, see docs/cluster.md) and kill one"
                    + " (SIGKILL) while the robot drives: the demo goes on with the others")
    private int cluster;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter stdout = spec.commandLine().getOut();
        DemoOptions options;
        try {
            options = new DemoOptions(Duration.ofMillis(Math.round(seconds * 1000)), Viewpoint.parse(viewpoint),
                    out, console, DemoOptions.defaultHome(), killControl).recording(record).clustered(cluster);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        DemoSummary summary = new Demo(options, stdout).run();
        return summary.succeeded() ? 0 : 1;
    }
}
