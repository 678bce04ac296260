package robotworld.program;

import java.io.PrintStream;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import robotworld.core.RuntimeSettings;

/**
 * The {@code main} of a generated participant program:
 *
 * <pre>{@code
 * public static void main(String[] args) {
 *     ParticipantMain.run(NAME, () -> {
 *         try (XVSMRuntime runtime = XVSMRuntime.connect(SPACE_URL, HOST)) {
 *             new CaterpillarRobot(runtime).control();
 *         }
 *     });
 * }
 * }</pre>
 *
 * The program's resources are closed by the program itself (try-with-resources), so closing the runtime, which
 * stops every actuator it owns, always happens before the process ends. When the program returns, the process
 * ends with status 0 even if a library left a thread running; when it fails, {@link Failures} reports the
 * failure in at most three lines that name the fix, and the process ends with status 1.
 */
public final class ParticipantMain {

    /** Set to {@code true} (or {@code RWE_DEBUG=true}) to see the full stack trace of a failure. */
    public static final String DEBUG_PROPERTY = "rwe.debug";

    /** Ports this program opened, so that a later failure on one can name the property that chooses it. */
    private static final Map<String, String> PORT_OWNERS = new ConcurrentHashMap<>();

    /** A participant program: connects, builds the participant, runs its control program. */
    @FunctionalInterface
    public interface Program {
        void run() throws Exception;
    }

    /** Opens a port given by name, e.g. {@code RS485Bus::new} or {@code CM11aController::open}. */
    @FunctionalInterface
    public interface PortOpener<T> {
        T open(String port) throws Exception;
    }

    private ParticipantMain() {
    }

    /**
     * Runs the program, reports a failure, and ends the process: status 0 when it returned, 1 when it failed. The
     * runtime's log goes to standard output, with what the program prints; standard error is left for the report
     * of a failure (and what the program itself writes there).
     */
    public static void run(String participant, Program program) {
        logToStandardOutput();
        int status = runReporting(participant, program, System.err);
        System.err.flush();
        System.out.flush();
        System.exit(status);
    }

    /** Runs the program and reports a failure on {@code err}; returns the exit status (for tests and embedding). */
    public static int runReporting(String participant, Program program, PrintStream err) {
        try {
            program.run();
            return 0;
        } catch (Throwable failure) {
            report(participant, failure, err);
            if (failure instanceof InterruptedException) {
                Thread.currentThread().interrupt();
            }
            return 1;
        }
    }

    /** Prints the lines of {@link Failures#describe} and, with {@code -Drwe.debug=true}, the stack trace. */
    public static void report(String participant, Throwable failure, PrintStream err) {
        List<String> lines = Failures.describe(failure, participant);
        lines.forEach(err::println);
        if (debug()) {
            failure.printStackTrace(err);
        }
    }

    /**
     * Points the runtime's log (SLF4J, written by Jetty's appender) at standard output. With another logging
     * back end on the class path, its own configuration decides.
     */
    static void logToStandardOutput() {
        try {
            if (org.slf4j.LoggerFactory.getILoggerFactory() instanceof org.eclipse.jetty.logging.JettyLoggerFactory jetty
                    && jetty.getJettyLogger(ParticipantMain.class.getName()).getAppender()
                    instanceof org.eclipse.jetty.logging.StdErrAppender appender) {
                appender.setStream(System.out);
            }
        } catch (LinkageError noJettyLogging) {
            // a program assembled without Jetty's logging: nothing to point elsewhere
        }
    }

    /** Whether failures are shown with their stack traces ({@code -Drwe.debug=true} or {@code RWE_DEBUG=true}). */
    public static boolean debug() {
        String value = System.getProperty(DEBUG_PROPERTY);
        if (value == null) {
            value = System.getenv("RWE_DEBUG");
        }
        return "true".equalsIgnoreCase(value == null ? null : value.strip());
    }

    /**
     * Opens a participant's port: the run-time override ({@code rwe.port.<participant>.<kind>} or
     * {@code RWE_PORT_<PARTICIPANT>_<KIND>}) or {@code fromDescription}.
     *
     * @param kind {@code bus} or {@code x10}
     * @throws PortException naming the participant, kind and port when it cannot be opened
     * @throws IllegalStateException when no port is set anywhere (the message names the property)
     */
    public static <T> T open(String participant, String kind, String fromDescription, PortOpener<T> opener)
            throws PortException {
        Objects.requireNonNull(opener, "opener");
        String port = RuntimeSettings.fromSystem().port(participant, kind, fromDescription);
        try {
            T opened = Objects.requireNonNull(opener.open(port), "opened port");
            PORT_OWNERS.put(port, participant + "\u0000" + kind);
            return opened;
        } catch (Exception e) {
            throw new PortException(participant, kind, port, e);
        }
    }

    /** The system property that chooses a participant's port of the given kind. */
    public static String portProperty(String participant, String kind) {
        return "rwe.port." + participant + "." + kind;
    }

    /** The property that chose {@code port} in this program, or null if this program did not open it. */
    static String propertyOf(String port) {
        String owner = port == null ? null : PORT_OWNERS.get(port);
        if (owner == null) {
            return null;
        }
        int separator = owner.indexOf('\u0000');
        return portProperty(owner.substring(0, separator), owner.substring(separator + 1));
    }
}
