package robotworld.bus;

/** The module did not answer (completely) within the timeout, in any of the attempts: it is absent or silent. */
public class BusTimeoutException extends BusException {

    public BusTimeoutException(String port, int address, String message) {
        super(port, address, message);
    }
}
