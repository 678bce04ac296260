package robotworld.bus;

import java.io.IOException;

/** A serial device that another program holds (its lock file, or an open handle, says so); the message names it. */
public final class PortInUseException extends IOException {

    private final String portName;

    public PortInUseException(String portName, String what) {
        super(portName + ": " + what);
        this.portName = portName;
    }

    /** The device that was refused. */
    public String portName() {
        return portName;
    }
}
