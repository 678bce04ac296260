package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;

/**
 * Clients that send their requests very slowly (a bad link, or an attack: one byte a second) hold connections,
 * not the server's threads, so a correct client is served as fast as before. The server here has far fewer
 * threads than slow connections, so any thread held per slow request would stop it.
 */
@org.junit.jupiter.api.Timeout(180)
class SlowSendersTest {

    private static final int SLOW_CONNECTIONS = 2_000;
    private static final int CALLS = 21;

    @Test
    void twoThousandSlowSendersDoNotDelayACorrectClient() throws Exception {
        // 64 waiting places: a thread pool of about 220, a tenth of the slow connections
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100).maxWaitingCalls(64);
        List<Socket> slow = new ArrayList<>();
        try (SpaceServer server = SpaceServer.start(options); RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO).named("queue"));
            long[] before = timeCalls(client, queue, CALLS);

            openSlowRequests(server, SLOW_CONNECTIONS, slow);
            Thread trickle = new Thread(() -> trickle(slow), "slow-senders");
            trickle.setDaemon(true);
            trickle.start();
            try {
                long[] during = timeCalls(client, queue, CALLS);
                long medianDelayMillis = TimeUnit.NANOSECONDS.toMillis(during[CALLS / 2] - before[CALLS / 2]);
                long slowestMillis = TimeUnit.NANOSECONDS.toMillis(during[CALLS - 1]);
                // a thread held per slow request would stop the server outright: the bound leaves room for a
                // busy machine and still tells the two apart
                assertTrue(medianDelayMillis <= 1_000, SLOW_CONNECTIONS + " slow senders delayed a call by "
                        + medianDelayMillis + " ms (median); before " + Arrays.toString(before) + ", during "
                        + Arrays.toString(during) + " ns");
                assertTrue(slowestMillis < 5_000, "the slowest call took " + slowestMillis + " ms");
            } finally {
                trickle.interrupt();
            }
            assertEquals(0, server.space().describeContainer(queue).size(), "no slow request was half-applied");
        } finally {
            for (Socket socket : slow) {
                socket.close();
            }
        }
    }

    /** Opens {@code count} connections, each with the head of a write whose 1000-byte body has not come yet. */
    static void openSlowRequests(SpaceServer server, int count, List<Socket> into) throws IOException {
        String head = "POST " + server.uri().getPath() + "/write HTTP/1.1\r\nHost: x\r\nContent-Type: "
                + "application/json\r\nContent-Length: 1000\r\n\r\n{";
        for (int i = 0; i < count; i++) {
            Socket socket = new Socket();
            socket.connect(new InetSocketAddress(server.uri().getHost(), server.port()), 10_000);
            socket.getOutputStream().write(head.getBytes(StandardCharsets.US_ASCII));
            into.add(socket);
        }
    }

    /** Each call is a write and a take on its own connection's exchange; their durations, sorted. */
    static long[] timeCalls(RemoteSpace client, ContainerRef queue, int calls) {
        long[] nanos = new long[calls];
        for (int i = 0; i < calls; i++) {
            long started = System.nanoTime();
            client.write(queue, Timeout.TRY_ONCE, Entry.of(i));
            assertEquals(List.of(Entry.of(i)), client.take(queue, Timeout.ofMillis(10_000)));
            nanos[i] = System.nanoTime() - started;
        }
        Arrays.sort(nanos);
        return nanos;
    }

    /** One more byte of every slow body each second, as a slow sender keeps its connection alive. */
    static void trickle(List<Socket> sockets) {
        byte[] space = {' '};
        while (!Thread.currentThread().isInterrupted()) {
            for (Socket socket : sockets) {
                try {
                    socket.getOutputStream().write(space);
                } catch (IOException closed) {
                    // the server may drop a slow connection: that is allowed
                }
            }
            try {
                Thread.sleep(1_000);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
