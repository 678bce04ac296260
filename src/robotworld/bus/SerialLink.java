package robotworld.bus;

import java.io.Closeable;
import java.io.IOException;
import java.time.Duration;

/**
 * A full-duplex byte link to a device: a local serial port or a raw serial-over-TCP bridge. Protocol code above
 * this interface does not know which one it talks to.
 *
 * <p>Reads never block longer than the timeout given; a peer that has gone away is reported as
 * {@link LinkClosedException}, never as an endless run of empty reads. A link is used by one reader thread and
 * one writer thread at a time; callers that share a link must serialise their own access.
 */
public interface SerialLink extends Closeable {

    /** The port name this link was made for, e.g. {@code /dev/ttyUSB0} or {@code tcp://127.0.0.1:5000}. */
    String portName();

    /**
     * Opens the link. Opening an open link does nothing.
     *
     * @throws IOException naming the port when it cannot be opened (missing device, refused connection, ...)
     */
    void open() throws IOException;

    /** Whether {@link #open()} succeeded and {@link #close()} has not been called since. */
    boolean isOpen();

    /** Writes all of {@code bytes}; returns once they are handed to the operating system. */
    void write(byte[] bytes) throws IOException;

    /** Writes one byte (the low eight bits of {@code value}). */
    default void write(int value) throws IOException {
        write(new byte[] {(byte) value});
    }

    /**
     * Reads what is available, up to {@code length} bytes, waiting at most {@code timeout} for the first byte.
     *
     * @return the number of bytes read, at least 1, or 0 when the timeout passed without data
     * @throws LinkClosedException when the peer has closed the link or the device is gone
     */
    int read(byte[] buffer, int offset, int length, Duration timeout) throws IOException;

    /**
     * Reads one byte, waiting at most {@code timeout}.
     *
     * @return the byte as 0..255, or -1 when the timeout passed without data
     */
    default int readByte(Duration timeout) throws IOException {
        byte[] one = new byte[1];
        return read(one, 0, 1, timeout) == 1 ? one[0] & 0xFF : -1;
    }

    /**
     * Whether a peer that says nothing may be a connection that died without being closed (a network bridge that
     * crashed or was cut off), so that opening the link again can help; a local serial port that is silent has a
     * silent device behind it, and opening it again does not.
     */
    default boolean silenceMayMeanADeadConnection() {
        return false;
    }

    /** The number of bytes that can be read now without waiting. */
    int available() throws IOException;

    /** Closes the link; a thread blocked in {@link #read} returns soon after. Closing twice does nothing. */
    @Override
    void close() throws IOException;
}
