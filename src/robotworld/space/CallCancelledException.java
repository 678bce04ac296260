package robotworld.space;

/**
 * The call was cancelled by its client before it arrived, so it was refused and had no effect. A server answers it
 * as cancelled; a client that cancels a call it lost sees this only if it sends the call again under the same id.
 */
public class CallCancelledException extends SpaceException {

    /** With a message. */
    public CallCancelledException(String message) {
        super(message);
    }
}
