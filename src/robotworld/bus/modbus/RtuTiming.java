package robotworld.bus.modbus;

import java.time.Duration;

/**
 * Timing of Modbus RTU at a line speed: character time, the 1.5- and 3.5-character silences that delimit frames
 * (fixed at 750 us and 1.75 ms above 19200 baud, as the Modbus serial-line specification recommends), and the
 * time frames take on the wire.
 */
public record RtuTiming(long characterNanos, long t15Nanos, long t35Nanos) {

    /**
     * The timing of a line.
     *
     * @param baudRate bits per second
     * @param characterNanos how long one character (start, data, parity and stop bits) takes
     */
    public static RtuTiming of(int baudRate, long characterNanos) {
        long character = characterNanos;
        if (baudRate > 19_200) {
            return new RtuTiming(character, 750_000L, 1_750_000L);
        }
        return new RtuTiming(character, Math.round(character * 1.5), Math.round(character * 3.5));
    }

    /** How long {@code bytes} characters take on the wire. */
    public long wireNanos(int bytes) {
        return characterNanos * bytes;
    }

    /** {@link #wireNanos} as a Duration. */
    public Duration wireTime(int bytes) {
        return Duration.ofNanos(wireNanos(bytes));
    }

    /** The silence that ends a frame. */
    public Duration frameGap() {
        return Duration.ofNanos(t35Nanos);
    }
}
