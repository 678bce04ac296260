package robotworld.safety;

import java.util.Locale;

/**
 * Why an actuator was put into its safe state. Travels in stop records as its {@link #wireName()}
 * ({@code program-ended}, {@code commander-silent}, ...).
 */
public enum StopCause {
    /** The program that serves the actuator ended normally (its runtime was closed). */
    PROGRAM_ENDED,
    /** The program that serves the actuator ended with an uncaught exception. */
    PROGRAM_FAILED,
    /** The program's JVM is shutting down: Ctrl-C, SIGTERM or {@code System.exit}. */
    SHUTDOWN,
    /** A program that commanded the actuator from another computer has been silent for the command timeout. */
    COMMANDER_SILENT,
    /** A program that commanded the actuator from another computer ended (it said so in its last heartbeat). */
    COMMANDER_ENDED,
    /** The program that serves the actuator could not reach its space for the command timeout. */
    SPACE_LOST,
    /** Someone asked to stop the world: {@code rwe stop} or a STOP button. */
    STOP_REQUEST,
    /** The module's own communication watchdog tripped: its master was silent for the watchdog timeout. */
    WATCHDOG;

    /** The name in stop records: lower case with dashes, e.g. {@code commander-silent}. */
    public String wireName() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** The cause of a wire name; unknown names (from a newer program) read as {@link #STOP_REQUEST}. */
    public static StopCause ofWireName(String name) {
        for (StopCause cause : values()) {
            if (cause.wireName().equals(name)) {
                return cause;
            }
        }
        return STOP_REQUEST;
    }

    /** Whether the program serving the actuator is ending: it refuses every later command. */
    public boolean endsTheProgram() {
        return this == PROGRAM_ENDED || this == PROGRAM_FAILED || this == SHUTDOWN;
    }
}
