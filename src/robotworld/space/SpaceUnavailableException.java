package robotworld.space;

import java.net.URI;

/**
 * The space could not be reached: no connection, the connection broke, or the server is stopping or too busy.
 * Carries the address that failed. A remote call retries such failures by itself until its deadline; this is
 * thrown when the deadline passes (or, for a call whose outcome cannot be known, at once).
 */
public class SpaceUnavailableException extends SpaceException {

    private final URI address;

    /** With the address that failed, a message and the cause. */
    public SpaceUnavailableException(URI address, String message, Throwable cause) {
        super(message + " (" + address + ")", cause);
        this.address = address;
    }

    /** The URL of the space server that could not be reached. */
    public URI address() {
        return address;
    }
}
