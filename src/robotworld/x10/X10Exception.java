package robotworld.x10;

/**
 * An X10 command could not be carried out through the CM11A. Unchecked, because the module interfaces of the
 * framework ({@code on()}, {@code off()}, ...) declare none; the runtime turns it into an error answer.
 */
public class X10Exception extends RuntimeException {

    private final String portName;

    public X10Exception(String portName, String message) {
        this(portName, message, null);
    }

    public X10Exception(String portName, String message, Throwable cause) {
        super("CM11A on " + portName + ": " + message, cause);
        this.portName = portName;
    }

    /** The port of the CM11A concerned. */
    public String portName() {
        return portName;
    }
}
