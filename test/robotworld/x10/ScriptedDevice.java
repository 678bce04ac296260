package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.time.Duration;
import robotworld.bus.SerialLink;

/** The device end of an in-memory link, driven step by step by a test: expect these bytes, answer those. */
final class ScriptedDevice {

    /** How long to wait for the host's bytes: they come at once, unless the machine is very busy. */
    private static final Duration WAIT = Duration.ofSeconds(30);

    private final SerialLink link;

    ScriptedDevice(SerialLink link) {
        this.link = link;
    }

    /** Reads as many bytes as {@code hex} has and asserts they are those. */
    ScriptedDevice expect(String hex) throws IOException {
        byte[] expected = Bytes.of(hex);
        byte[] got = new byte[expected.length];
        int filled = 0;
        while (filled < got.length) {
            int n = link.read(got, filled, got.length - filled, WAIT);
            if (n == 0) {
                break;
            }
            filled += n;
        }
        assertEquals(hex.toUpperCase(), Hex.of(got, 0, filled), "bytes from the host");
        return this;
    }

    /** Sends {@code hex} to the host. */
    ScriptedDevice send(String hex) throws IOException {
        link.write(Bytes.of(hex));
        return this;
    }

    /** Asserts the host sends nothing for {@code millis}. */
    ScriptedDevice expectSilence(long millis) throws IOException {
        int value = link.readByte(Duration.ofMillis(millis));
        assertEquals(-1, value, "the host should be silent");
        return this;
    }

    /** Reads {@code length} bytes, whatever they are. */
    byte[] read(int length) throws IOException {
        byte[] got = new byte[length];
        int filled = 0;
        while (filled < length) {
            int n = link.read(got, filled, length - filled, WAIT);
            if (n == 0) {
                throw new AssertionError("only " + filled + " of " + length + " bytes came");
            }
            filled += n;
        }
        return got;
    }
}
