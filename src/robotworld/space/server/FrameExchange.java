package robotworld.space.server;

import java.net.InetAddress;

import robotworld.space.wire.Frames;
import robotworld.space.wire.WireContext;

/** An operation that came as a request frame on a {@link FrameConnection}, answered with an answer frame. */
final class FrameExchange extends Exchange {

    private final FrameConnection connection;
    /** The connection closes after this answer (a refused connection, a frame that could not be read). */
    boolean closing;

    FrameExchange(FrameConnection connection, WireContext wire, InetAddress client) {
        super(wire, client);
        this.connection = connection;
    }

    @Override
    void transmit(int status, byte[] body, boolean retryLater) {
        connection.answer(status, body, (retryLater ? Frames.RETRY_LATER : 0) | (closing ? Frames.CLOSING : 0));
    }

    @Override
    void abandon(Throwable cause) {
        connection.abandon();
    }
}
