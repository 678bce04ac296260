package robotworld.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.time.Duration;
import robotworld.bus.SerialLink;
import robotworld.bus.SerialLinks;
import robotworld.x10.Hex;
import robotworld.x10.X10Constants;

/** A host that speaks to the simulator byte by byte, so tests see exactly what the interface answers. */
final class RawHost implements AutoCloseable {

    private static final Duration WAIT = Duration.ofSeconds(2);

    final SerialLink link;

    RawHost(String portName) throws IOException {
        link = SerialLinks.open(portName, X10Constants.CM11A_SERIAL);
    }

    RawHost send(String hex) throws IOException {
        link.write(bytes(hex));
        return this;
    }

    /** Reads as many bytes as {@code hex} has and asserts they are those. */
    RawHost expect(String hex) throws IOException {
        byte[] got = read(bytes(hex).length);
        assertEquals(hex.toUpperCase(), Hex.of(got), "bytes from the interface");
        return this;
    }

    /**
     * As {@link #expect}, after any number of {@code poll} bytes: a polling interface may poll once more before it
     * takes what the host sent (a poll interval can pass on a busy machine).
     */
    RawHost expectAfterPolls(String poll, String hex) throws IOException {
        byte[] first = read(1);
        while (first.length == 1 && Hex.of(first).equalsIgnoreCase(poll) && !poll.equalsIgnoreCase(hex)) {
            first = read(1);
        }
        byte[] rest = read(bytes(hex).length - 1);
        byte[] got = new byte[first.length + rest.length];
        System.arraycopy(first, 0, got, 0, first.length);
        System.arraycopy(rest, 0, got, first.length, rest.length);
        assertEquals(hex.toUpperCase(), Hex.of(got), "bytes from the interface");
        return this;
    }

    byte[] read(int length) throws IOException {
        byte[] got = new byte[length];
        int filled = 0;
        while (filled < length) {
            int n = link.read(got, filled, length - filled, WAIT);
            if (n == 0) {
                break;
            }
            filled += n;
        }
        return java.util.Arrays.copyOf(got, filled);
    }

    /** The next byte within {@code millis}, or -1. */
    int next(long millis) throws IOException {
        return link.readByte(Duration.ofMillis(millis));
    }

    static byte[] bytes(String hex) {
        String[] parts = hex.trim().split("\\s+");
        byte[] bytes = new byte[parts.length];
        for (int i = 0; i < parts.length; i++) {
            bytes[i] = (byte) Integer.parseInt(parts[i], 16);
        }
        return bytes;
    }

    @Override
    public void close() throws IOException {
        link.close();
    }
}
