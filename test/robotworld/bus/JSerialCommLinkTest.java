package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** jSerialComm on a socat pty pair: the same path a USB serial adapter takes. */
class JSerialCommLinkTest {

    private static final SerialSettings CM11A = SerialSettings.eightNoneOne(4800);

    private SocatPty pty;

    @BeforeEach
    void startPty() throws Exception {
        pty = SocatPty.start();
    }

    @AfterEach
    void stopPty() throws Exception {
        if (pty != null) { // null when the set-up was skipped (no socat)
            pty.close();
        }
    }

    @Test
    void bytesTravelBothWaysUnchanged() throws IOException {
        try (SerialLink host = SerialLinks.open(pty.a().toString(), CM11A);
                SerialLink device = SerialLinks.open(pty.b().toString(), CM11A)) {
            assertTrue(host instanceof JSerialCommLink);
            byte[] all = new byte[256];
            for (int i = 0; i < all.length; i++) {
                all[i] = (byte) i;
            }
            host.write(all);
            assertArrayEquals(all, TcpSerialLinkTest.readExactly(device, all.length));
            device.write(new byte[] {0x5A, (byte) 0xC3});
            assertArrayEquals(new byte[] {0x5A, (byte) 0xC3}, TcpSerialLinkTest.readExactly(host, 2));
        }
    }

    @Test
    void readReturnsNothingAfterTheTimeout() throws IOException {
        try (SerialLink host = SerialLinks.open(pty.a().toString(), CM11A)) {
            long start = System.nanoTime();
            assertEquals(-1, host.readByte(Duration.ofMillis(50)));
            long elapsedMs = (System.nanoTime() - start) / 1_000_000;
            // the upper bound only tells "returned" from "hung": a busy machine may add much to a 50 ms wait
            assertTrue(elapsedMs >= 40 && elapsedMs < 5_000, "waited " + elapsedMs + " ms");
            assertEquals(0, host.read(new byte[4], 0, 4, Duration.ZERO));
        }
    }

    @Test
    void missingDeviceNamesThePath() {
        String missing = pty.a().resolveSibling("no-such-port").toString();
        IOException e = assertThrows(IOException.class, () -> SerialLinks.open(missing, CM11A));
        assertTrue(e.getMessage().contains(missing), e.getMessage());
    }
}
