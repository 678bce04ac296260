package robotworld.xvsm;

/**
 * The module's host performed the call and the hardware failed (a refusing bus module, corrupted replies, a
 * broken link, ...). It travelled back as an error answer; this carries what the host reported: the host's name,
 * the exception type it saw and its message.
 */
public class XVSMRemoteException extends ModuleCallException {

    private final String remoteHost;
    private final String remoteType;
    private final String remoteMessage;

    /** With the module's coordinates and the host's report. */
    public XVSMRemoteException(String participant, String module, String function, String remoteHost,
                               String remoteType, String remoteMessage) {
        super(participant, module, function, participant + "/" + module + " " + function + " failed on host "
                + remoteHost + ": " + remoteType + ": " + remoteMessage, null);
        this.remoteHost = remoteHost;
        this.remoteType = remoteType;
        this.remoteMessage = remoteMessage;
    }

    /** The host that serves the module and reported the failure. */
    public String remoteHost() {
        return remoteHost;
    }

    /** The fully qualified class name of the exception at the module's host. */
    public String remoteType() {
        return remoteType;
    }

    /** That exception's message. */
    public String remoteMessage() {
        return remoteMessage;
    }
}
