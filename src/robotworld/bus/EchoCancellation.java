package robotworld.bus;

/**
 * What the master does about an RS-485 adapter that echoes every request it sends (a half-duplex adapter without
 * echo suppression hears itself): the request's own bytes then arrive before the reply.
 */
public enum EchoCancellation {
    /**
     * Looks for the echo and, once a request has come back byte for byte ahead of its reply, drops each request's
     * echo from then on (and says so once in the log). Only requests whose reply can never equal them are taken
     * as proof, so a device that answers a write by repeating it is never mistaken for an echo. The default.
     */
    AUTO,
    /** Drops each request's echo before the reply; a request that does not come back is no error. */
    ON,
    /** Takes the bytes as they come; an echo fails the call with {@link AdapterEchoException}, which says so. */
    OFF;

    /** Parses auto, on or off, in any case. */
    public static EchoCancellation parse(String text) {
        try {
            return valueOf(text.trim().toUpperCase(java.util.Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("echo cancellation '" + text + "' is none of auto, on, off");
        }
    }
}
