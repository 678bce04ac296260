package robotworld.space;

/**
 * The operation can never succeed on this container as asked: a key or vector selector or item on a container
 * without that view, more entries than the capacity, duplicate keys or positions in one write, and the like.
 * It fails at once instead of waiting forever.
 */
public class InvalidOperationException extends SpaceException {

    /** With a message. */
    public InvalidOperationException(String message) {
        super(message);
    }
}
