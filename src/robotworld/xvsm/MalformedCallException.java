package robotworld.xvsm;

/**
 * A request or answer tuple does not have the layout its module expects (wrong arity or field type, an unknown
 * function). A module's host answers such a request with an error answer instead of touching the hardware.
 */
public class MalformedCallException extends RuntimeException {

    public MalformedCallException(String message) {
        super(message);
    }
}
