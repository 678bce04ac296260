package robotworld.bus;

import java.io.IOException;

/** A serial device that another program holds (its lock file, or an open handle, says so); the message names it. */
public final class PortInUseException extends IOException {

    private final String portName;
    private final String holder;

    /**
     * @param holder who holds it, e.g. "heyu (process 1234)"
     * @param what the rest of the message after the port name
     */
    public PortInUseException(String portName, String holder, String what) {
        super(portName + ": " + what);
        this.portName = portName;
        this.holder = holder;
    }

    /** The device that was refused. */
    public String portName() {
        return portName;
    }

    /** Who holds it, e.g. "heyu (process 1234)", or "this program". */
    public String holder() {
        return holder;
    }
}
