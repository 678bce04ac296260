package robotworld.bus;

/**
 * The reply began with the request itself: the adapter echoes what it sends, and echo cancellation is off. Every
 * call on this bus will fail the same way until it is turned on.
 */
public final class AdapterEchoException extends BusProtocolException {

    public AdapterEchoException(String portName, int address, String message) {
        super(portName, address, message);
    }
}
