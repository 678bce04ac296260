package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Duration;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
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

    /**
     * Closing a port while another thread is inside a read of it crashed the JVM (jSerialComm's native read then
     * used the closed port). A close now waits for the call under way to end (a read at its timeout), the reader is
     * told the link was closed, and the port can be opened again at once. Bytes keep coming meanwhile, so reads find
     * some and go into the port, by both of the link's ways of reading (short waits polled, long ones in the port).
     */
    @Test
    void closingWhileAnotherThreadReadsEndsTheReadAndNeverCrashes() throws Exception {
        Random random = new Random(7);
        try (SerialLink device = SerialLinks.open(pty.b().toString(), CM11A)) {
            Thread talker = new Thread(() -> {
                try {
                    while (true) {
                        device.write(new byte[] {1, 2, 3, 4});
                        Thread.sleep(1);
                    }
                } catch (Exception closed) {
                    // the test is over
                }
            }, "pty-talker");
            talker.setDaemon(true);
            talker.start();
            for (int round = 0; round < 40; round++) {
                closeWhileReading(Duration.ofMillis(round % 2 == 0 ? 20 : 150), random.nextInt(60));
            }
        }
    }

    private void closeWhileReading(Duration timeout, int afterMillis) throws Exception {
        SerialLink host = SerialLinks.open(pty.a().toString(), CM11A);
        CompletableFuture<Throwable> ended = new CompletableFuture<>();
        Thread reader = new Thread(() -> {
            try {
                while (true) {
                    host.read(new byte[64], 0, 64, timeout);
                }
            } catch (Throwable e) {
                ended.complete(e);
            }
        }, "pty-reader");
        reader.start();
        Thread.sleep(afterMillis);
        long start = System.nanoTime();
        host.close();
        long closeMillis = (System.nanoTime() - start) / 1_000_000;
        Throwable why = ended.get(5, TimeUnit.SECONDS);
        assertTrue(why instanceof LinkClosedException, "the reader ended with " + why);
        assertTrue(closeMillis < 5_000, "close took " + closeMillis + " ms");
        try (SerialLink again = SerialLinks.open(pty.a().toString(), CM11A)) {
            assertTrue(again.isOpen(), "the port is free again once close returned");
        }
    }
}
