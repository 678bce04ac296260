package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
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
 * What one client may hold of a server: connections and waiting operations per remote address, and the time a
 * request may take to arrive. The greedy client here connects from 127.0.0.2 (loopback, another address); the
 * well-behaved one from 127.0.0.1, and is served all along.
 */
@org.junit.jupiter.api.Timeout(120)
class ClientLimitsTest {

    private static final String JSON = "application/json";
    private static final String TOKEN = "client-limits-secret";

    @Test
    void connectionsBeyondTheAddressLimitAreRefusedWhileOthersAreServed() throws Exception {
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100)
                .maxConnectionsPerClient(3);
        try (SpaceServer server = SpaceServer.start(options); RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef empty = client.createContainer(ContainerSpec.of(Order.FIFO));
            List<Socket> greedy = new ArrayList<>();
            try {
                // the first, closed below, waits less: the server notices a closed connection when it answers
                greedy.add(waitingTake(server, greedyAddress(), empty, null, 5_000));
                for (int i = 1; i < 3; i++) {
                    greedy.add(waitingTake(server, greedyAddress(), empty, null));
                }
                awaitBlocked(client, empty, 3);
                RawHttp.Answer refused = RawHttp.sendFrom(greedyAddress(), server.uri(), "POST "
                        + server.uri().getPath() + "/lookup HTTP/1.1\r\nContent-Type: " + JSON
                        + "\r\nContent-Length: 15\r\n", "{\"name\":\"any\"}".getBytes(StandardCharsets.UTF_8));
                assertEquals(503, refused.status(), refused.head() + "\n" + refused.body());
                assertTrue(refused.body().startsWith("{\"error\":\"busy\""), refused.body());
                assertTrue(refused.body().contains("maxConnectionsPerClient"), refused.body());

                // another address is served as before, waits included
                ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO));
                client.write(queue, Timeout.TRY_ONCE, Entry.of("served"));
                assertEquals(List.of(Entry.of("served")), client.take(queue, Timeout.ofMillis(5_000)));

                // once one of its connections closes, the address is served again (at the latest when the
                // closed connection's waiting take ends)
                greedy.remove(0).close();
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                RawHttp.Answer again;
                do {
                    Thread.sleep(20);
                    again = RawHttp.sendFrom(greedyAddress(), server.uri(), "GET " + server.uri().getPath()
                            + " HTTP/1.1\r\n", new byte[0]);
                } while (again.status() == 503 && System.nanoTime() < deadline);
                assertEquals(200, again.status(), again.body());
            } finally {
                for (Socket socket : greedy) {
                    socket.close();
                }
            }
        }
    }

    @Test
    void aClientWithTheTokenIsNotLimitedPerAddress() throws Exception {
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100).token(TOKEN)
                .maxConnectionsPerClient(1).maxWaitingPerClient(1);
        try (SpaceServer server = SpaceServer.start(options)) {
            ContainerRef empty = server.space().createContainer(ContainerSpec.of(Order.FIFO));
            List<Socket> waiting = new ArrayList<>();
            try {
                for (int i = 0; i < 3; i++) {
                    waiting.add(waitingTake(server, greedyAddress(), empty, TOKEN));
                }
                awaitBlocked(server.space(), empty, 3);
                RawHttp.Answer withoutToken = RawHttp.sendFrom(greedyAddress(), server.uri(), "GET "
                        + server.uri().getPath() + " HTTP/1.1\r\n", new byte[0]);
                assertEquals(503, withoutToken.status(), withoutToken.body());
                assertTrue(withoutToken.body().contains("maxConnectionsPerClient"), withoutToken.body());
            } finally {
                for (Socket socket : waiting) {
                    socket.close();
                }
            }
        }
    }

    @Test
    void waitingOperationsBeyondTheAddressLimitAreToldToComeBackWhileOthersWait() throws Exception {
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100)
                .maxWaitingPerClient(2);
        try (SpaceServer server = SpaceServer.start(options); RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef empty = client.createContainer(ContainerSpec.of(Order.FIFO));
            List<Socket> greedy = new ArrayList<>();
            try {
                for (int i = 0; i < 2; i++) {
                    greedy.add(waitingTake(server, greedyAddress(), empty, null));
                }
                awaitBlocked(client, empty, 2);
                String body = takeBody(empty, 10_000);
                RawHttp.Answer third = RawHttp.sendFrom(greedyAddress(), server.uri(), "POST "
                        + server.uri().getPath() + "/take HTTP/1.1\r\nContent-Type: " + JSON + "\r\nContent-Length: "
                        + body.length() + "\r\n", body.getBytes(StandardCharsets.UTF_8));
                assertEquals(503, third.status(), third.body());
                assertTrue(third.body().startsWith("{\"error\":\"busy\""), third.body());
                assertTrue(third.body().contains("maxWaitingPerClient"), third.body());
                assertTrue(third.head().contains("Retry-After"), third.head());

                // another address still waits, and gets its entry
                ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO));
                Thread writer = new Thread(() -> {
                    try {
                        Thread.sleep(300);
                        server.space().write(queue, Timeout.TRY_ONCE, Entry.of("for the patient one"));
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                });
                writer.start();
                assertEquals(List.of(Entry.of("for the patient one")), client.take(queue, Timeout.ofMillis(10_000)));
                writer.join();
            } finally {
                for (Socket socket : greedy) {
                    socket.close();
                }
            }
        }
    }

    @Test
    void aTricklingSenderIsCutOffAtTheRequestDeadline() throws Exception {
        long deadlineMillis = 1_000;
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100)
                .requestReadMillis(deadlineMillis);
        try (SpaceServer server = SpaceServer.start(options);
             Socket slow = new Socket(server.uri().getHost(), server.port())) {
            slow.setSoTimeout(100);
            long started = System.nanoTime();
            slow.getOutputStream().write(("POST " + server.uri().getPath() + "/write HTTP/1.1\r\nHost: x\r\n"
                    + "Content-Type: " + JSON + "\r\nContent-Length: 1000\r\n\r\n{").getBytes(StandardCharsets.US_ASCII));
            boolean cut = false;
            // a byte every 100 ms would keep an idle timeout from ever running out; the documented bound is the
            // deadline plus two sweeps (of a quarter of it here): the wide margin is for a busy machine
            while (!cut && System.nanoTime() - started < TimeUnit.SECONDS.toNanos(15)) {
                try {
                    slow.getOutputStream().write(' ');
                    cut = slow.getInputStream().read() < 0;
                } catch (SocketTimeoutException stillOpen) {
                    // nothing from the server yet
                } catch (SocketException closed) {
                    cut = true;
                }
            }
            long elapsedMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            assertTrue(cut, "a request trickling for " + elapsedMillis + " ms was not cut off");
            assertTrue(elapsedMillis >= deadlineMillis, "cut after " + elapsedMillis + " ms, before the deadline");
        }
    }

    @Test
    void idleConnectionsAndLongWaitsAreNotCutByTheRequestDeadline() throws Exception {
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100)
                .requestReadMillis(500);
        try (SpaceServer server = SpaceServer.start(options);
             Socket socket = new Socket(server.uri().getHost(), server.port())) {
            ContainerRef empty = server.space().createContainer(ContainerSpec.of(Order.FIFO));
            socket.setSoTimeout(10_000);
            // a take that waits 2 s, four deadlines, for nothing: answered with its timeout, not cut
            String body = takeBody(empty, 2_000);
            String request = "POST " + server.uri().getPath() + "/take HTTP/1.1\r\nHost: x\r\nContent-Type: " + JSON
                    + "\r\nContent-Length: " + body.length() + "\r\n\r\n" + body;
            socket.getOutputStream().write(request.getBytes(StandardCharsets.US_ASCII));
            assertTrue(readAnswer(socket.getInputStream()).startsWith("HTTP/1.1 409"));
            // then idle for four deadlines, and the same connection carries the next request
            Thread.sleep(2_000);
            String lookup = "{\"name\":\"nothing here\"}";
            socket.getOutputStream().write(("POST " + server.uri().getPath() + "/lookup HTTP/1.1\r\nHost: x\r\n"
                    + "Content-Type: " + JSON + "\r\nContent-Length: " + lookup.length() + "\r\n\r\n" + lookup)
                    .getBytes(StandardCharsets.US_ASCII));
            assertTrue(readAnswer(socket.getInputStream()).startsWith("HTTP/1.1 404"));
        }
    }

    private static InetAddress greedyAddress() throws IOException {
        return InetAddress.getByName("127.0.0.2");
    }

    private static String takeBody(ContainerRef container, long timeoutMillis) {
        return "{\"container\":{\"cref\":\"" + container.id() + "\",\"space\":\"" + container.space()
                + "\"},\"timeout\":" + timeoutMillis + "}";
    }

    /** A take that waits (10 s) on its own connection from {@code from}, left unanswered. */
    private static Socket waitingTake(SpaceServer server, InetAddress from, ContainerRef empty, String token)
            throws IOException {
        return waitingTake(server, from, empty, token, 10_000);
    }

    private static Socket waitingTake(SpaceServer server, InetAddress from, ContainerRef empty, String token,
                                      long waitMillis) throws IOException {
        String body = takeBody(empty, waitMillis);
        Socket socket = new Socket();
        socket.bind(new InetSocketAddress(from, 0));
        socket.connect(new InetSocketAddress(server.uri().getHost(), server.port()), 10_000);
        socket.getOutputStream().write(("POST " + server.uri().getPath() + "/take HTTP/1.1\r\nHost: x\r\n"
                + (token == null ? "" : "Authorization: Bearer " + token + "\r\n")
                + "Content-Type: " + JSON + "\r\nContent-Length: " + body.length() + "\r\n\r\n" + body)
                .getBytes(StandardCharsets.US_ASCII));
        return socket;
    }

    private static void awaitBlocked(robotworld.space.Capi space, ContainerRef container, int count)
            throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (space.describeContainer(container).blocked() < count) {
            assertTrue(System.nanoTime() < deadline, "the takes never waited");
            Thread.sleep(5);
        }
    }

    /** Reads one answer with a Content-Length body; returns its head and body. */
    private static String readAnswer(InputStream in) throws IOException {
        ByteArrayOutputStream head = new ByteArrayOutputStream();
        while (!head.toString(StandardCharsets.ISO_8859_1).endsWith("\r\n\r\n")) {
            int b = in.read();
            if (b < 0) {
                throw new IOException("connection closed before the answer: " + head);
            }
            head.write(b);
        }
        String text = head.toString(StandardCharsets.ISO_8859_1);
        int length = 0;
        for (String line : text.split("\r\n")) {
            if (line.toLowerCase(java.util.Locale.ROOT).startsWith("content-length:")) {
                length = Integer.parseInt(line.substring(15).trim());
            }
        }
        byte[] body = in.readNBytes(length);
        return text + new String(body, StandardCharsets.UTF_8);
    }
}
