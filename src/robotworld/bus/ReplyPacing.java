package robotworld.bus;

import java.util.Arrays;
import java.util.OptionalLong;

/**
 * How fast the bytes of replies arrive, measured per address from frames that came in several pieces: modules that
 * talk at a slower baud rate than the master's (a forgotten {@code --baud} behind a serial bridge) send their bytes
 * further apart than the line's character time. A baud-rate mismatch slows every module alike, whereas a module
 * with slow firmware (one that trickles its reply) slows only itself; so the replies count as paced at another rate
 * only when most of the addresses that sent valid frames are slow. Frames that came in one piece say nothing about
 * the pace, but they do show that their address answered. Thread-safe.
 */
public final class ReplyPacing {

    /** The common baud rates of serial lines, slowest first. */
    public static final int[] COMMON_BAUD_RATES = {1200, 2400, 4800, 9600, 19_200, 38_400, 57_600, 115_200,
        230_400};

    private static final int SAMPLES = 16;
    private final long characterNanos;
    /** Per address: the time between two bytes of its last frames that came in pieces (null: none seen). */
    private final long[][] perCharacter = new long[256][];
    private final int[] measured = new int[256];
    private final boolean[] answered = new boolean[256];

    ReplyPacing(long characterNanos) {
        this.characterNanos = characterNanos;
    }

    /**
     * A valid frame from {@code address} of {@code length} bytes came in {@code reads} pieces, {@code spanNanos} from
     * first to last.
     */
    synchronized void frameReceived(int address, int length, int reads, long spanNanos) {
        int slot = address & 0xFF;
        answered[slot] = true;
        if (reads < 3 || length < 6 || spanNanos <= 0) {
            return;
        }
        if (perCharacter[slot] == null) {
            perCharacter[slot] = new long[SAMPLES];
        }
        perCharacter[slot][measured[slot] % SAMPLES] = spanNanos / (length - 1);
        measured[slot]++;
    }

    /** The median time between two bytes of a reply, over the last frames from all addresses that came in pieces. */
    public synchronized OptionalLong medianCharacterNanos() {
        long[] all = new long[0];
        for (int slot = 0; slot < 256; slot++) {
            if (measured[slot] > 0) {
                long[] mine = samples(slot);
                long[] both = Arrays.copyOf(all, all.length + mine.length);
                System.arraycopy(mine, 0, both, all.length, mine.length);
                all = both;
            }
        }
        return median(all);
    }

    /** The median time between two bytes of replies from {@code address}, when some of its frames came in pieces. */
    public synchronized OptionalLong medianCharacterNanos(int address) {
        return measured[address & 0xFF] == 0 ? OptionalLong.empty() : median(samples(address & 0xFF));
    }

    /**
     * The common baud rate the replies look like when the replies of most addresses that sent valid frames come at
     * least twice as slowly as this line's own character time (bits per character of the line's settings), else
     * empty. One or two slow modules among others at the line's pace are slow modules, not a mismatch.
     *
     * @param bitsPerCharacter start, data, parity and stop bits
     */
    public synchronized OptionalLong slowerLineBaud(int bitsPerCharacter) {
        int answering = 0;
        long[] slow = new long[0];
        for (int slot = 0; slot < 256; slot++) {
            if (!answered[slot]) {
                continue;
            }
            answering++;
            OptionalLong median = medianCharacterNanos(slot);
            if (median.isPresent() && median.getAsLong() >= 2 * characterNanos) {
                // the rate from this address's fastest slow frame: a stall (a busy machine, either end) only ever
                // stretches a frame, so the median of stretched frames would name too slow a rate
                long fastest = Long.MAX_VALUE;
                for (long sample : samples(slot)) {
                    if (sample >= 2 * characterNanos) {
                        fastest = Math.min(fastest, sample);
                    }
                }
                slow = Arrays.copyOf(slow, slow.length + 1);
                slow[slow.length - 1] = fastest;
            }
        }
        if (slow.length == 0 || 2 * slow.length <= answering) {
            return OptionalLong.empty();
        }
        double baud = bitsPerCharacter * 1e9 / median(slow).getAsLong();
        int nearest = COMMON_BAUD_RATES[0];
        for (int rate : COMMON_BAUD_RATES) {
            if (Math.abs(Math.log(rate / baud)) < Math.abs(Math.log(nearest / baud))) {
                nearest = rate;
            }
        }
        return OptionalLong.of(nearest);
    }

    private long[] samples(int slot) {
        return Arrays.copyOf(perCharacter[slot], Math.min(measured[slot], SAMPLES));
    }

    private static OptionalLong median(long[] samples) {
        if (samples.length == 0) {
            return OptionalLong.empty();
        }
        long[] sorted = samples.clone();
        Arrays.sort(sorted);
        return OptionalLong.of(sorted[sorted.length / 2]);
    }
}
