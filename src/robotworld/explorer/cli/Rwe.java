package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robotworld.explorer.RobotWorldExplorer;
import robotworld.program.Failures;
import robotworld.program.ParticipantMain;

/**
 * The {@code rwe} command line: one verb per job, each a picocli subcommand class in this package.
 * Exit codes: 0 success, 1 the job failed (e.g. an invalid description), 2 wrong usage. Without a verb it opens
 * the {@link RobotWorldExplorer} window on a desktop, and says that a verb is missing everywhere else.
 *
 * <p>Errors are short: a usage error is its message and {@code see 'rwe VERB --help'}; a failure of the job is at
 * most three lines that name the fix ({@link Failures}); a stack trace only with {@code -Drwe.debug=true}.
 */
@Command(name = "rwe", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "RobotWorldExplorer: describe robots and environments, generate and run control frameworks.",
        subcommands = {ValidateCommand.class, ExploreCommand.class, AssembleCommand.class, GenerateCommand.class,
                SimulateCommand.class, SpaceCommand.class, MonitorCommand.class, StopCommand.class, DemoCommand.class,
                RecordCommand.class, ReplayCommand.class, BridgeCommand.class, CommandLine.HelpCommand.class})
public final class Rwe implements Callable<Integer> {

    private static final Pattern NOT_A_NUMBER = Pattern.compile(
            "Invalid value for (?:option|positional parameter) '([^']+)': '(.*)' is not an? (?:int|long|double|float)");

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
        joinDescriptionLines(commandLine);
        commandLine.setParameterExceptionHandler(Rwe::usageError);
        commandLine.setExecutionExceptionHandler((exception, line, parseResult) -> {
            reportFailure(exception, line);
            return 1;
        });
        return commandLine.execute(args);
    }

    /**
     * Descriptions are written in the source as lines of about 100 characters; picocli prints each element on a line
     * of its own and wraps it at 80, which leaves stubs of a word or two. Lines of one sentence are joined into one
     * paragraph (a line ending a sentence or a list item ends it) so that picocli wraps whole paragraphs.
     */
    private static void joinDescriptionLines(CommandLine line) {
        var usage = line.getCommandSpec().usageMessage();
        java.util.List<String> paragraphs = new java.util.ArrayList<>();
        StringBuilder paragraph = new StringBuilder();
        for (String each : usage.description()) {
            if (paragraph.length() > 0) {
                paragraph.append(' ');
            }
            paragraph.append(each.strip());
            if (each.endsWith(".") || each.endsWith(":") || each.endsWith(")") && !each.contains("(see")) {
                paragraphs.add(paragraph.toString());
                paragraph.setLength(0);
            }
        }
        if (paragraph.length() > 0) {
            paragraphs.add(paragraph.toString());
        }
        usage.description(paragraphs.toArray(String[]::new));
        line.getSubcommands().values().forEach(Rwe::joinDescriptionLines);
    }

    /** A usage error: the message in words, then where the usage is, never the usage itself. */
    private static int usageError(ParameterException exception, String[] args) {
        CommandLine line = exception.getCommandLine();
        PrintWriter err = line.getErr();
        String verb = verb(line);
        String message = inWords(exception.getMessage());
        if (verb.isEmpty() && exception instanceof picocli.CommandLine.UnmatchedArgumentException unmatched
                && !unmatched.getUnmatched().isEmpty() && !unmatched.getUnmatched().get(0).startsWith("-")) {
            // the first word was meant as a verb
            message = "unknown verb '" + unmatched.getUnmatched().get(0) + "'; the verbs are "
                    + String.join(", ", line.getSubcommands().keySet());
        }
        err.println((verb.isEmpty() ? "rwe" : "rwe " + verb) + ": " + message);
        err.println("see 'rwe " + (verb + " --help").strip() + "'");
        err.flush();
        return 2;
    }

    /** A failure of the job: at most three lines naming the fix; the trace only with -Drwe.debug=true. */
    static void reportFailure(Exception exception, CommandLine line) {
        PrintWriter err = line.getErr();
        CommandSpec spec = line.getCommandSpec();
        Failures.Fixes fixes = Failures.Fixes.command(
                spec.findOption("--port") != null ? "--port" : null,
                spec.findOption("--space") != null ? "--space URL" : null);
        var lines = Failures.describe(exception, null, fixes);
        for (int i = 0; i < lines.size(); i++) {
            err.println(i == 0 ? "rwe " + verb(line) + ": " + lines.get(i) : lines.get(i));
        }
        if (ParticipantMain.debug()) {
            StringWriter trace = new StringWriter();
            exception.printStackTrace(new PrintWriter(trace));
            err.print(trace);
        }
        err.flush();
    }

    /** "explore", "simulate robot": the command's name after {@code rwe}. */
    static String verb(CommandLine line) {
        String qualified = line.getCommandSpec().qualifiedName(" ");
        return qualified.startsWith("rwe") ? qualified.substring(3).strip() : qualified;
    }

    /** picocli's wording where it is not the user's. */
    static String inWords(String message) {
        if (message == null) {
            return "wrong usage";
        }
        Matcher number = NOT_A_NUMBER.matcher(message);
        if (number.find()) {
            return number.group(1).replaceAll("=.*", "") + ": '" + number.group(2) + "' is not a number";
        }
        return message.replace("Missing required option: ", "missing option ")
                .replace("Missing required options: ", "missing options ")
                .replace("Missing required parameter: ", "missing ")
                .replace("Missing required parameters: ", "missing ")
                .replace("Unknown option: ", "unknown option ")
                .replace("Unknown options: ", "unknown options ")
                .replace("Unmatched argument at index ", "unexpected argument at position ");
    }

    /** No verb: the launcher on a desktop; otherwise the list of verbs, with exit code 2. */
    @Override
    public Integer call() throws InterruptedException {
        if (robotworld.explorer.monitor.gui.Display.usable()) {
            RobotWorldExplorer.showAndWait();
            return 0;
        }
        PrintWriter err = spec.commandLine().getErr();
        err.println("rwe: name a verb: " + String.join(", ", spec.subcommands().keySet().stream()
                .filter(name -> !name.equals("help")).toList()));
        err.println("see 'rwe --help'");
        return 2;
    }
}
