package robotworld.space;

/** The operation could not be done within its timeout (at once, for {@link Timeout#TRY_ONCE}). */
public class SpaceTimeoutException extends SpaceException {

    /** With a message. */
    public SpaceTimeoutException(String message) {
        super(message);
    }
}
