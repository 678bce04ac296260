package robotworld.space.wire;

import robotworld.space.SpaceException;

/**
 * A message does not follow the wire format (see {@code docs/wire.md}): bad JSON, a wrong type, a value out of
 * range, or a limit exceeded. The server answers it with 400; a client that receives a malformed answer throws it.
 */
public class WireFormatException extends SpaceException {

    /** With a message that says what was wrong and where. */
    public WireFormatException(String message) {
        super(message);
    }

    /** With a message and the parser's failure. */
    public WireFormatException(String message, Throwable cause) {
        super(message, cause);
    }
}
