package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import robotworld.space.EmbeddedSpace;

/**
 * A server that stops, or is killed, closes every connection it accepted, including those it accepted while it was
 * stopping. One left open answers nothing and never closes: its client (a cancel sent right after the server
 * broke its connection, say) waits out its whole network allowance on a server that is gone, while the server
 * started in its place could have answered at once.
 */
class StoppingClosesEveryConnectionTest {

    private static final int ROUNDS = 30;
    /** How long a connection of a stopped server may stay open: the kernel closes it at once, or not at all. */
    private static final int CLOSED_WITHIN_MILLIS = 3_000;

    private EmbeddedSpace space;
    private ExecutorService threads;

    @BeforeEach
    void open() {
        space = EmbeddedSpace.open();
        threads = Executors.newCachedThreadPool();
    }

    @AfterEach
    void close() throws InterruptedException {
        threads.shutdownNow();
        assertTrue(threads.awaitTermination(5, TimeUnit.SECONDS));
        space.close();
    }

    @Test
    void aKilledServerLeavesNoConnectionOpen() throws Exception {
        assertNoneLeftOpen(true);
    }

    @Test
    void aStoppedServerLeavesNoConnectionOpen() throws Exception {
        assertNoneLeftOpen(false);
    }

    /** At its connection limit a server stops accepting; stopping it then must still close its port. */
    @Test
    void aServerStoppedAtItsConnectionLimitStopsListening() throws Exception {
        for (boolean kill : new boolean[] {false, true}) {
            SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0).stopGraceMillis(50)
                    .maxConnections(1));
            int port = server.port();
            try (Socket first = new Socket()) {
                first.connect(new InetSocketAddress("127.0.0.1", port), 1_000);
                Thread.sleep(200); // accepted: the server is at its limit and has stopped accepting
                if (kill) {
                    server.kill();
                } else {
                    server.stop();
                }
                assertTrue(!staysOpen(first), "the connection of a stopped server is closed");
            }
            try (Socket late = new Socket()) {
                late.connect(new InetSocketAddress("127.0.0.1", port), 1_000);
                late.getOutputStream().write("GET /space HTTP/1.1\r\nHost: x\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
                assertTrue(!staysOpen(late), "a stopped server still listens on port " + port + " and answers nothing");
            } catch (IOException refused) {
                // refused: nothing listens any more
            }
        }
    }

    private void assertNoneLeftOpen(boolean kill) throws Exception {
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(50);
        int connected = 0;
        List<String> leftOpen = new ArrayList<>();
        for (int round = 0; round < ROUNDS; round++) {
            SpaceServer server = SpaceServer.start(space, options);
            int port = server.port();
            List<Socket> sockets = new ArrayList<>();
            AtomicBoolean connecting = new AtomicBoolean(true);
            // clients keep connecting while the server goes down, as a client settling its broken call does
            Future<?> connector = threads.submit(() -> {
                while (connecting.get()) {
                    Socket socket = new Socket();
                    try {
                        socket.connect(new InetSocketAddress("127.0.0.1", port), 1_000);
                        socket.getOutputStream().write(("POST /space/describe HTTP/1.1\r\nHost: x\r\n"
                                + "Content-Length: 2\r\n\r\n{}").getBytes(StandardCharsets.US_ASCII));
                        synchronized (sockets) {
                            sockets.add(socket);
                        }
                    } catch (IOException refused) {
                        closeQuietly(socket);
                        return null; // the server is gone
                    }
                }
                return null;
            });
            Thread.sleep(5 + round % 7);
            if (kill) {
                server.kill();
            } else {
                server.stop();
            }
            connecting.set(false);
            connector.get(10, TimeUnit.SECONDS);
            synchronized (sockets) {
                connected += sockets.size();
                for (Socket socket : sockets) {
                    if (staysOpen(socket)) {
                        leftOpen.add("round " + round + ", port " + socket.getLocalPort());
                    }
                    closeQuietly(socket);
                }
            }
        }
        assertTrue(connected >= ROUNDS / 3, "the clients connected " + connected + " times: too few to tell");
        assertEquals(List.of(), leftOpen, "connections the stopped server neither answered nor closed");
    }

    /** Reads to the end: whether the connection stayed open, silent, for {@link #CLOSED_WITHIN_MILLIS}. */
    private static boolean staysOpen(Socket socket) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(CLOSED_WITHIN_MILLIS);
        try {
            InputStream in = socket.getInputStream();
            byte[] buffer = new byte[4096];
            while (true) {
                long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
                if (left <= 0) {
                    return true;
                }
                socket.setSoTimeout((int) left);
                if (in.read(buffer) < 0) {
                    return false; // answered (a keep-alive answer is read past), then closed
                }
            }
        } catch (SocketTimeoutException silent) {
            return true;
        } catch (IOException reset) {
            return false;
        }
    }

    private static void closeQuietly(Socket socket) {
        try {
            socket.close();
        } catch (IOException ignored) {
            // nothing to do
        }
    }
}
