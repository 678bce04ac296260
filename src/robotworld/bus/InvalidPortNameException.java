package robotworld.bus;

/** A port name that is neither a serial device nor a well-formed {@code tcp://host:port}. */
public class InvalidPortNameException extends IllegalArgumentException {

    public InvalidPortNameException(String message) {
        super(message);
    }
}
