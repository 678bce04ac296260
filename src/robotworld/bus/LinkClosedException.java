package robotworld.bus;

import java.io.IOException;

/** The other end of a {@link SerialLink} has gone away (TCP peer closed, USB adapter unplugged, pty closed). */
public class LinkClosedException extends IOException {

    private final String portName;

    public LinkClosedException(String portName, String message) {
        super(portName + ": " + message);
        this.portName = portName;
    }

    /** The port whose peer went away. */
    public String portName() {
        return portName;
    }
}
