package robotworld.xvsm;

/**
 * A call on a module shared through the space did not complete. Unchecked, because the thesis's module interfaces
 * declare no exceptions; the message names the participant, the module, the function and the host involved.
 * Subclasses say why: {@link XVSMRemoteException} (the module's host reported a failure) and
 * {@link ModuleCallTimeoutException} (no answer in time). This class itself is used when the space failed
 * (unreachable, closed) or the calling thread was interrupted.
 */
public class ModuleCallException extends RuntimeException {

    private final String participant;
    private final String module;
    private final String function;

    /** With the module's coordinates, a complete message and the cause (may be null). */
    public ModuleCallException(String participant, String module, String function, String message,
                               Throwable cause) {
        super(message, cause);
        this.participant = participant;
        this.module = module;
        this.function = function;
    }

    /** The participant (robot or environment) the module belongs to. */
    public String participant() {
        return participant;
    }

    /** The module's name in the description. */
    public String module() {
        return module;
    }

    /** The function that was called, e.g. {@code getSingleBumper}. */
    public String function() {
        return function;
    }
}
