package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.Timeout;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.TcpBlackhole;

/**
 * A server that does not answer, as opposed to one that refuses: the host crashed, packets are dropped, its
 * accept queue is full, or it accepts and then stays silent. Every call still ends within its timeout plus the
 * network allowance with {@link SpaceUnavailableException} (never an interrupt, never a raw exception), leaves the
 * caller's interrupt flag alone, and works again once the server is back.
 */
@org.junit.jupiter.api.Timeout(120)
class UnreachableServerTest {

    /** The default network allowance (3 s). */
    private static final long ALLOWANCE_MILLIS = 3_000;
    /**
     * What a busy machine may add to a bound: less than one more network allowance, so a call that spends its
     * allowance twice (the way calls overran before: about 6 s instead of 3 s) fails the test.
     */
    private static final long SLACK_MILLIS = 2_000;

    private EmbeddedSpace space;
    private SpaceServer server;
    private TcpBlackhole blackhole;
    private final List<RemoteSpace> clients = new ArrayList<>();

    @BeforeEach
    void start() throws Exception {
        space = EmbeddedSpace.open();
        server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
        blackhole = new TcpBlackhole("127.0.0.1", server.port());
    }

    @AfterEach
    void stop() throws Exception {
        clients.forEach(RemoteSpace::close);
        blackhole.close();
        server.stop();
        space.close();
    }

    private RemoteSpace client() {
        RemoteSpace client = RemoteSpace.open(URI.create("http://127.0.0.1:" + blackhole.port() + "/space"),
                RemoteSpace.Options.defaults().networkAllowanceMillis(ALLOWANCE_MILLIS));
        clients.add(client);
        return client;
    }

    @Test
    void aSilentServerGivesUnavailableWithinTheBoundAndNoInterrupt() throws Exception {
        RemoteSpace client = client();
        ContainerRef jobs = client.createContainer(ContainerSpec.of(Order.FIFO).named("jobs"));
        blackhole.blackhole(); // the pooled connection stays open: the server has become silent

        long timeoutMillis = 500;
        long started = System.nanoTime();
        assertThrows(SpaceUnavailableException.class, () -> client.take(jobs, Timeout.ofMillis(timeoutMillis)));
        long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
        assertTrue(tookMillis < timeoutMillis + ALLOWANCE_MILLIS + SLACK_MILLIS, "took " + tookMillis + " ms");
        assertFalse(Thread.currentThread().isInterrupted(), "a silent server is not an interrupt");

        started = System.nanoTime();
        assertThrows(SpaceUnavailableException.class, () -> client.write(jobs, Timeout.TRY_ONCE, Entry.of(1)));
        tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
        assertTrue(tookMillis < ALLOWANCE_MILLIS + SLACK_MILLIS, "a call that does not wait: took " + tookMillis);
        assertFalse(Thread.currentThread().isInterrupted());
    }

    @Test
    void aTakeWaitingWithoutAThreadOnASilentServerEndsUnavailableWithinTheBound() throws Exception {
        RemoteSpace client = client();
        ContainerRef jobs = client.createContainer(ContainerSpec.of(Order.FIFO).named("jobs"));
        blackhole.blackhole();

        long timeoutMillis = 500;
        CompletableFuture<Object> outcome = new CompletableFuture<>();
        long started = System.nanoTime();
        client.takeLater(jobs, Timeout.ofMillis(timeoutMillis), new Selector[0], new SpaceEngine.Completion<>() {
            @Override
            public void completed(List<Entry> entries) {
                outcome.complete(entries);
            }

            @Override
            public void failed(SpaceException failure) {
                outcome.complete(failure);
            }
        });
        Object ended = outcome.get(timeoutMillis + 3 * ALLOWANCE_MILLIS + SLACK_MILLIS, TimeUnit.MILLISECONDS);
        long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
        assertTrue(ended instanceof SpaceUnavailableException, "ended with " + ended);
        assertTrue(tookMillis < timeoutMillis + ALLOWANCE_MILLIS + SLACK_MILLIS, "took " + tookMillis + " ms");
    }

    @Test
    void aServerThatDoesNotAcceptGivesUnavailableWithinTheBound() throws Exception {
        RemoteSpace client = client();
        ContainerRef jobs = client.createContainer(ContainerSpec.of(Order.FIFO).named("jobs"));
        blackhole.blackhole();
        Thread.sleep(100);
        for (int i = 0; i < 3; i++) { // the first call finds the pooled connection silent, the later ones connect
            long started = System.nanoTime();
            assertThrows(SpaceUnavailableException.class, () -> client.take(jobs, Timeout.ofMillis(300)));
            long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            assertTrue(tookMillis < 300 + ALLOWANCE_MILLIS + SLACK_MILLIS, "took " + tookMillis + " ms");
            assertFalse(Thread.currentThread().isInterrupted());
        }
    }

    @Test
    void callsWorkAgainWhenTheServerIsBack() throws Exception {
        RemoteSpace client = client();
        ContainerRef jobs = client.createContainer(ContainerSpec.of(Order.FIFO).named("jobs"));
        blackhole.blackhole();
        assertThrows(SpaceUnavailableException.class, () -> client.take(jobs, Timeout.ofMillis(200)));
        blackhole.restore();

        long giveUp = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (true) {
            try {
                client.write(jobs, Timeout.ofMillis(1_000), Entry.of(7));
                break;
            } catch (SpaceUnavailableException stillGone) {
                assertTrue(System.nanoTime() < giveUp, "the client never reached the server again");
            }
        }
        assertEquals(List.of(Entry.of(7)), client.take(jobs, Timeout.ofMillis(5_000)));
    }
}
