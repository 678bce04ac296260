package robotworld.space;

/**
 * The waiting thread was interrupted; the operation had no effect. The thread's interrupt flag is set again
 * before this is thrown.
 */
public class SpaceInterruptedException extends SpaceException {

    /** With a message and the interruption. */
    public SpaceInterruptedException(String message, InterruptedException cause) {
        super(message, cause);
    }
}
