package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class TcpSerialLinkTest {

    private ServerSocket server;

    @BeforeEach
    void listen() throws IOException {
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    }

    @AfterEach
    void stop() throws IOException {
        server.close();
    }

    private SerialLink connect() throws IOException {
        return SerialLinks.open("tcp://127.0.0.1:" + server.getLocalPort(), SerialSettings.eightNoneOne(4800));
    }

    @Test
    void bytesTravelBothWaysUnchanged() throws IOException {
        try (SerialLink host = connect(); Socket accepted = server.accept();
                SerialLink device = new TcpSerialLink(accepted)) {
            byte[] all = new byte[256];
            for (int i = 0; i < all.length; i++) {
                all[i] = (byte) i;
            }
            host.write(all);
            assertArrayEquals(all, readExactly(device, all.length));
            device.write(0xA5);
            assertEquals(0xA5, host.readByte(Duration.ofSeconds(30)));
        }
    }

    @Test
    void readReturnsNothingAfterTheTimeout() throws IOException {
        try (SerialLink host = connect(); Socket accepted = server.accept()) {
            assertTrue(accepted.isConnected());
            long start = System.nanoTime();
            assertEquals(-1, host.readByte(Duration.ofMillis(50)));
            long elapsedMs = (System.nanoTime() - start) / 1_000_000;
            // the upper bound only tells "returned" from "hung": a busy machine may add much to a 50 ms wait
            assertTrue(elapsedMs >= 40 && elapsedMs < 5_000, "waited " + elapsedMs + " ms");
            assertEquals(0, host.read(new byte[4], 0, 4, Duration.ZERO));
            assertEquals(0, host.available());
        }
    }

    @Test
    void peerClosingIsReportedNotRepeatedEmptyReads() throws IOException {
        try (SerialLink host = connect()) {
            server.accept().close();
            assertThrows(LinkClosedException.class, () -> host.readByte(Duration.ofSeconds(30)));
        }
    }

    @Test
    void refusedConnectionNamesThePort() throws IOException {
        int port = server.getLocalPort();
        server.close();
        IOException e = assertThrows(IOException.class,
                () -> SerialLinks.open("tcp://127.0.0.1:" + port, SerialSettings.eightNoneOne(4800)));
        assertTrue(e.getMessage().contains("tcp://127.0.0.1:" + port), e.getMessage());
    }

    @Test
    void reopenedLinkConnectsAgainAndKeepsItsTimeouts() throws IOException {
        SerialLink host = connect();
        try (Socket first = server.accept()) {
            assertEquals(-1, host.readByte(Duration.ofMillis(20)));
            host.close();
            host.open();
            try (Socket second = server.accept(); SerialLink device = new TcpSerialLink(second)) {
                long start = System.nanoTime();
                assertEquals(-1, host.readByte(Duration.ofMillis(20))); // must not wait forever
                assertTrue((System.nanoTime() - start) / 1_000_000 < 5_000);
                device.write(0x55);
                assertEquals(0x55, host.readByte(Duration.ofSeconds(30)));
            }
        } finally {
            host.close();
        }
    }

    @Test
    void closedLinkRefusesWork() throws IOException {
        SerialLink host = connect();
        host.close();
        host.close(); // twice is fine
        assertThrows(LinkClosedException.class, () -> host.write(1));
    }

    static byte[] readExactly(SerialLink link, int length) throws IOException {
        byte[] buffer = new byte[length];
        int filled = 0;
        while (filled < length) {
            int n = link.read(buffer, filled, length - filled, Duration.ofSeconds(30));
            if (n == 0) {
                throw new IOException("only " + filled + " of " + length + " bytes arrived");
            }
            filled += n;
        }
        return buffer;
    }
}
