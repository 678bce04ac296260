package robotworld.space;

/**
 * Any failure of a space operation; the subclasses say which. Unchecked, like the other failures of a
 * middleware call, but every blocking operation documents the ones it throws.
 */
public class SpaceException extends RuntimeException {

    /** With a message. */
    public SpaceException(String message) {
        super(message);
    }

    /** With a message and a cause. */
    public SpaceException(String message, Throwable cause) {
        super(message, cause);
    }
}
