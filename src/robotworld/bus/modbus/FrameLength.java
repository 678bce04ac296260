package robotworld.bus.modbus;

/**
 * Tells from the first bytes of an RTU frame how long the whole frame is. RTU delimits frames by 3.5 characters
 * of silence, but TCP bridges and pseudo-terminals do not keep silences, so both ends compute the length from the
 * function code and fall back to silence only for functions they do not know.
 */
@FunctionalInterface
public interface FrameLength {

    /** More bytes are needed before the length is known. */
    int NEED_MORE = 0;

    /** The length cannot be told from the bytes: the frame ends at the next silence. */
    int UNKNOWN = -1;

    /**
     * The total length of the frame in {@code buffer}, CRC included.
     *
     * @param buffer the bytes received so far, address first
     * @param have how many bytes of {@code buffer} are valid
     * @return the length, {@link #NEED_MORE} or {@link #UNKNOWN}
     */
    int of(byte[] buffer, int have);
}
