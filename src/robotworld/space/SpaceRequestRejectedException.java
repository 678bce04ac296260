package robotworld.space;

/**
 * A space server refused a request as such, not as a space operation: bad credentials (401), a malformed or
 * oversized request (400, 413, 415) or a protocol mismatch. Carries the HTTP status and the server's message.
 */
public class SpaceRequestRejectedException extends SpaceException {

    private final int status;

    /** With the HTTP status and a message. */
    public SpaceRequestRejectedException(int status, String message) {
        super(message);
        this.status = status;
    }

    /** The HTTP status code the server answered with (0 if the answer was not HTTP at all). */
    public int status() {
        return status;
    }
}
