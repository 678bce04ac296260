package robotworld.sim.robot;

import java.util.Locale;

/** How the simulated bus paces its replies. */
public enum LineTiming {
    /** Replies at once: for tests and quick runs. */
    FAST,
    /**
     * Replies as on a real line at the configured baud rate: after the request's wire time and the 3.5-character
     * silence, one byte per character time.
     */
    REAL;

    /** Parses {@code fast} or {@code real}, in any case. */
    public static LineTiming parse(String text) {
        try {
            return valueOf(text.trim().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("timing '" + text + "' is neither fast nor real");
        }
    }
}
