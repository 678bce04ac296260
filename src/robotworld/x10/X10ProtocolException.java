package robotworld.x10;

/** The CM11A answered, but not as the protocol requires, more often than the retries allow. */
public class X10ProtocolException extends X10Exception {

    public X10ProtocolException(String portName, String message) {
        super(portName, message);
    }
}
