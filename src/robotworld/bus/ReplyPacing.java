package robotworld.bus;

import java.util.Arrays;
import java.util.OptionalLong;

/**
 * How fast the bytes of replies arrive, measured from frames that came in several pieces: modules that talk at a
 * slower baud rate than the master's (a forgotten {@code --baud} behind a serial bridge) send their bytes further
 * apart than the line's character time. Frames that came in one piece say nothing and are not counted.
 * Thread-safe.
 */
public final class ReplyPacing {

    /** The common baud rates of serial lines, slowest first. */
    public static final int[] COMMON_BAUD_RATES = {1200, 2400, 4800, 9600, 19_200, 38_400, 57_600, 115_200,
        230_400};

    private static final int SAMPLES = 64;
    private final long characterNanos;
    private final long[] perCharacter = new long[SAMPLES];
    private int count;

    ReplyPacing(long characterNanos) {
        this.characterNanos = characterNanos;
    }

    /** A valid frame of {@code length} bytes came in {@code reads} pieces, {@code spanNanos} from first to last. */
    synchronized void frameReceived(int length, int reads, long spanNanos) {
        if (reads < 3 || length < 6 || spanNanos <= 0) {
            return;
        }
        perCharacter[count % SAMPLES] = spanNanos / (length - 1);
        count++;
    }

    /** The median time between two bytes of a reply, over the last frames that came in pieces. */
    public synchronized OptionalLong medianCharacterNanos() {
        if (count == 0) {
            return OptionalLong.empty();
        }
        long[] samples = Arrays.copyOf(perCharacter, Math.min(count, SAMPLES));
        Arrays.sort(samples);
        return OptionalLong.of(samples[samples.length / 2]);
    }

    /**
     * The common baud rate the replies look like when they come at least twice as slowly as this line's own
     * character time (bits per character of the line's settings), else empty.
     *
     * @param bitsPerCharacter start, data, parity and stop bits
     */
    public OptionalLong slowerLineBaud(int bitsPerCharacter) {
        OptionalLong median = medianCharacterNanos();
        if (median.isEmpty() || median.getAsLong() < 2 * characterNanos) {
            return OptionalLong.empty();
        }
        double baud = bitsPerCharacter * 1e9 / median.getAsLong();
        int nearest = COMMON_BAUD_RATES[0];
        for (int rate : COMMON_BAUD_RATES) {
            if (Math.abs(Math.log(rate / baud)) < Math.abs(Math.log(nearest / baud))) {
                nearest = rate;
            }
        }
        return OptionalLong.of(nearest);
    }
}
