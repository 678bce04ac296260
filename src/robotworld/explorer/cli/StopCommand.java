package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.stop.WorldStopper;
import robotworld.safety.WorldStop;

/**
 * {@code rwe stop WORLD [--space URL] [--wait SECONDS] [--reason TEXT]}: stops every actuator of a running world
 * through its space, from any computer, and reports per module.
 */
@Command(name = "stop", mixinStandardHelpOptions = true,
        description = {"Stop every actuator of a running RobotWorld, from any computer that",
                "reaches its space. Every program serving actuators of the world puts",
                "them into their safe state at once (motors 0, servos hold, X10 as",
                "configured) and answers; prints per participant and module: stopped,",
                "no actuator, or unreachable. See docs/safety.md.",
                "Exit code 0 when every actuator answered that it is stopped, 1 when",
                "one is unreachable or failed."})
final class StopCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "WORLD", description = "the RobotWorld description")
    private Path world;

    @Option(names = "--space", paramLabel = "URL[,URL...]",
            description = "the space server, or the servers of a clustered space separated by commas (default: "
                    + "rwe.space.url, RWE_SPACE_URL or the world's SpaceURL)")
    private String space;

    @Option(names = "--wait", paramLabel = "SECONDS", defaultValue = "2",
            description = "how long to wait for the answers (default: ${DEFAULT-VALUE})")
    private double seconds;

    @Option(names = "--reason", paramLabel = "TEXT", defaultValue = "",
            description = "why, for the stop records and logs of every program")
    private String reason;

    @Option(names = "--schemas", paramLabel = "DIR", description = "validate against the schemas in DIR")
    private Path schemaDirectory;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (!(seconds > 0) || seconds > 600) {
            throw new ParameterException(spec.commandLine(), "--wait must be more than 0 and at most 600 seconds");
        }
        MonitoredWorld loaded;
        try {
            DescriptionSchemas schemas = schemaDirectory == null ? DescriptionSchemas.configured()
                    : DescriptionSchemas.fromDirectory(schemaDirectory);
            loaded = MonitoredWorld.of(DescriptionLoader.loadWorld(world, schemas));
        } catch (DescriptionException e) {
            e.errors().stream().map(DescriptionError::toString).forEach(err::println);
            err.flush();
            return 1;
        }
        String url = MonitorSpace.url(space, loaded);
        err.println("stopping every actuator of " + loaded.name() + " through " + url);
        err.flush();
        WorldStop.Result result = WorldStopper.stop(loaded, url, "rwe stop", reason,
                Duration.ofMillis(Math.round(seconds * 1000)));
        WorldStopper.print(result, out);
        return result.complete() ? 0 : 1;
    }
}
