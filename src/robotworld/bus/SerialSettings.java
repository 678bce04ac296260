package robotworld.bus;

/**
 * Line settings of a serial port. A TCP link ignores them: the bridge on the other side owns the real port.
 *
 * @param baudRate bits per second, e.g. 4800
 * @param dataBits 5..8
 * @param parity parity bit
 * @param stopBits stop bits
 */
public record SerialSettings(int baudRate, int dataBits, Parity parity, StopBits stopBits) {

    /** Parity of each character. */
    public enum Parity { NONE, ODD, EVEN, MARK, SPACE }

    /** Number of stop bits after each character. */
    public enum StopBits { ONE, ONE_POINT_FIVE, TWO }

    public SerialSettings {
        if (baudRate <= 0) {
            throw new IllegalArgumentException("baud rate must be positive, was " + baudRate);
        }
        if (dataBits < 5 || dataBits > 8) {
            throw new IllegalArgumentException("data bits must be 5..8, was " + dataBits);
        }
        if (parity == null || stopBits == null) {
            throw new IllegalArgumentException("parity and stop bits are required");
        }
    }

    /** The common 8 data bits, no parity, one stop bit at {@code baudRate}. */
    public static SerialSettings eightNoneOne(int baudRate) {
        return new SerialSettings(baudRate, 8, Parity.NONE, StopBits.ONE);
    }

    /** Bits on the wire per character: start bit, data bits, parity bit if any, stop bits (1.5 rounds up). */
    public int bitsPerCharacter() {
        int stop = stopBits == StopBits.ONE ? 1 : 2;
        return 1 + dataBits + (parity == Parity.NONE ? 0 : 1) + stop;
    }

    /** How long one character takes on the wire at this baud rate, in nanoseconds. */
    public long characterTimeNanos() {
        return Math.round(bitsPerCharacter() * 1_000_000_000.0 / baudRate);
    }

    @Override
    public String toString() {
        return baudRate + " " + dataBits + parity.name().charAt(0)
                + (stopBits == StopBits.ONE ? "1" : stopBits == StopBits.TWO ? "2" : "1.5");
    }
}
