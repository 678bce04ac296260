package robotworld.space.server;

import java.net.Socket;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Order;
import robotworld.space.remote.RemoteSpace;

/**
 * How much 2 000 slow senders (request heads sent, bodies trickling one byte a second) delay a correct client's
 * write+take on a space server with the defaults a user gets (no token). Each run times the client's calls before
 * and while the slow connections are open, on the same server; the figure is the difference of the medians.
 * Knobs: {@code bench.runs} (5), {@code bench.calls} (201), {@code bench.slowConnections} (2000).
 */
public final class SlowSendersBenchmark {

    private static final long TARGET_MILLIS = 100;

    private static void closeAll(List<Socket> sockets) throws java.io.IOException {
        for (Socket socket : sockets) {
            socket.close();
        }
        sockets.clear();
    }

    public static void main(String[] args) throws Exception {
        int runs = Integer.getInteger("bench.runs", 5);
        int calls = Integer.getInteger("bench.calls", 201);
        int slowConnections = Integer.getInteger("bench.slowConnections", 2_000);
        System.out.printf("Slow senders: %d connections trickling a byte a second against a space server with its "
                + "defaults; %d runs x %d write+take calls before and during; %s, Java %s, %d CPUs%n%n", slowConnections,
                runs, calls, System.getProperty("os.name"), System.getProperty("java.version"),
                Runtime.getRuntime().availableProcessors());
        double[] delays = new double[runs];
        for (int run = 0; run < runs; run++) {
            List<Socket> slow = new ArrayList<>();
            try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0));
                    RemoteSpace client = RemoteSpace.open(server.uri())) {
                ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO).named("queue"));
                SlowSendersTest.timeCalls(client, queue, calls); // warm-up
                long[] before = SlowSendersTest.timeCalls(client, queue, calls);
                SlowSendersTest.openSlowRequests(server, slowConnections, slow);
                Thread trickle = new Thread(() -> SlowSendersTest.trickle(slow), "slow-senders");
                trickle.setDaemon(true);
                trickle.start();
                long[] during;
                try {
                    during = SlowSendersTest.timeCalls(client, queue, calls);
                } finally {
                    trickle.interrupt();
                }
                double p50Before = before[calls / 2] / 1e6;
                double p50During = during[calls / 2] / 1e6;
                delays[run] = p50During - p50Before;
                System.out.printf("run %d: call p50 %.3f ms before, %.3f ms with %d slow senders (delay %+.3f ms); "
                        + "max during %.1f ms%n", run + 1, p50Before, p50During, slowConnections, delays[run],
                        during[calls - 1] / 1e6);
                closeAll(slow); // before the server stops: it would wait for their requests
            } finally {
                closeAll(slow);
            }
        }
        Arrays.sort(delays);
        double median = delays[runs / 2];
        System.out.printf("%nmedian delay of a correct client's call by %d slow senders: %.3f ms (target <= %d ms: %s)%n",
                slowConnections, median, TARGET_MILLIS, median <= TARGET_MILLIS ? "met" : "NOT met");
    }
}
