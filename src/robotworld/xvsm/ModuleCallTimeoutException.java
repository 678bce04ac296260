package robotworld.xvsm;

/**
 * No answer in time: either the module's host did not answer within the call timeout (it is not running, or is
 * too busy), or the module's hardware itself did not answer its host (a silent bus module, a CM11A that is off).
 * The message says which, and names the module and the host.
 */
public class ModuleCallTimeoutException extends ModuleCallException {

    private final long timeoutMillis;

    /**
     * @param timeoutMillis the call timeout that ran out, or -1 when the hardware timed out at the module's host
     */
    public ModuleCallTimeoutException(String participant, String module, String function, long timeoutMillis,
                                      String message) {
        super(participant, module, function, message, null);
        this.timeoutMillis = timeoutMillis;
    }

    /** The call timeout that ran out, in ms; -1 when it was the hardware that timed out at the module's host. */
    public long timeoutMillis() {
        return timeoutMillis;
    }

    /** Whether the hardware timed out at the module's host (rather than the host not answering at all). */
    public boolean hardwareTimedOut() {
        return timeoutMillis < 0;
    }
}
