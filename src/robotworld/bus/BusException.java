package robotworld.bus;

/**
 * A call on the module bus failed. Unchecked, because the module interfaces ({@code robotworld.core}) declare no
 * checked exceptions, as in the thesis. The message names the module (when known), its address and the port.
 * Subclasses tell the kind of failure; this class itself is used when the link failed.
 */
public class BusException extends RuntimeException {

    private final String port;
    private final int address;

    public BusException(String port, int address, String message, Throwable cause) {
        super(message, cause);
        this.port = port;
        this.address = address;
    }

    public BusException(String port, int address, String message) {
        this(port, address, message, null);
    }

    /** The port of the bus, e.g. {@code tcp://127.0.0.1:5020}. */
    public String port() {
        return port;
    }

    /** The bus address the call went to. */
    public int address() {
        return address;
    }
}
