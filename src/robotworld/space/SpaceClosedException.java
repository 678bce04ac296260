package robotworld.space;

/** The space was closed, before or while the operation was waiting. */
public class SpaceClosedException extends SpaceException {

    /** With a message. */
    public SpaceClosedException(String message) {
        super(message);
    }
}
