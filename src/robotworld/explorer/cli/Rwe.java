package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import robotworld.explorer.RobotWorldExplorer;

/**
 * The {@code rwe} command line: one verb per job, each a picocli subcommand class in this package.
 * Exit codes: 0 success, 1 the job failed (e.g. an invalid description), 2 wrong usage. Without a verb it opens
 * the {@link RobotWorldExplorer} window on a desktop, and says that a verb is missing everywhere else.
 */
@Command(name = "rwe", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "RobotWorldExplorer: describe robots and environments, generate and run control frameworks.",
        subcommands = {ValidateCommand.class, ExploreCommand.class, GenerateCommand.class, SimulateCommand.class,
                SpaceCommand.class, MonitorCommand.class, StopCommand.class, DemoCommand.class, RecordCommand.class,
                ReplayCommand.class, BridgeCommand.class, CommandLine.HelpCommand.class})
public final class Rwe implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    public static void main(String[] args) {
        System.exit(run(args));
    }

    /** Runs the command line without exiting the JVM; returns the exit code. */
    public static int run(String... args) {
        return run(new PrintWriter(System.out, true), new PrintWriter(System.err, true), args);
    }

    /** Runs the command line with the given output and error writers; returns the exit code. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        CommandLine commandLine = new CommandLine(new Rwe()).setOut(out).setErr(err);
        // a failure inside a verb is reported as one line, never as a stack trace
        commandLine.setExecutionExceptionHandler((exception, line, parseResult) -> {
            line.getErr().println("rwe: " + exception.getMessage());
            return 1;
        });
        return commandLine.execute(args);
    }

    /** No verb: the launcher on a desktop; otherwise the usage, as before, with exit code 2. */
    @Override
    public Integer call() throws InterruptedException {
        if (robotworld.explorer.monitor.gui.Display.usable()) {
            RobotWorldExplorer.showAndWait();
            return 0;
        }
        spec.commandLine().getErr().println("Missing required subcommand");
        spec.commandLine().usage(spec.commandLine().getErr());
        return 2;
    }
}
