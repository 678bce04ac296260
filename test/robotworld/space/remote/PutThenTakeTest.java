package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Timeout;
import robotworld.space.Tuple;
import robotworld.space.server.SpaceServer;

/**
 * {@code writeThenTake} and {@code shiftThenTake}: one request on a remote space, the same outcome as the two
 * operations one after the other (the embedded space's default), including when the take's part of the server's
 * wait runs out, when the take times out (the write stays done), and when the caller is interrupted (the take has
 * no effect).
 */
@org.junit.jupiter.api.Timeout(120)
class PutThenTakeTest {

    private EmbeddedSpace space;
    private SpaceServer server;
    private RemoteSpace a;
    private RemoteSpace b;
    private ExecutorService threads;
    private ContainerRef requests;
    private ContainerRef answers;

    @BeforeEach
    void start() {
        space = EmbeddedSpace.open();
        // a short server wait, so the take's part of it runs out and the client asks again
        server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0).maxWaitMillis(100));
        // a network allowance a busy machine does not use up: these tests are about the exchange, not the network
        // (a freshly started server on a loaded machine took longer than the default 3 s to answer the first call)
        RemoteSpace.Options patient = RemoteSpace.Options.defaults().networkAllowanceMillis(30_000);
        a = RemoteSpace.open(server.uri(), patient);
        b = RemoteSpace.open(server.uri(), patient);
        threads = Executors.newCachedThreadPool();
        requests = a.createContainer(ContainerSpec.of(Order.FIFO).named("REQUEST"));
        answers = a.createContainer(ContainerSpec.of(Order.LIFO).withKeyView().named("ANSWER"));
    }

    @AfterEach
    void stop() {
        threads.shutdownNow();
        a.close();
        b.close();
        server.stop();
        space.close();
    }

    @Test
    void aRequestAnswerExchangeInOneRequestPerSide() throws Exception {
        Future<?> module = threads.submit(() -> {
            Tuple request = (Tuple) b.take(requests, Timeout.ofMillis(30_000)).get(0);
            for (int i = 0; i < 3; i++) {
                Item answer = Item.keyed(request.stringAt(0), Tuple.of(request.longAt(1) * 10));
                request = (Tuple) b.shiftThenTake(answers, List.of(answer), requests, Timeout.ofMillis(30_000)).get(0);
            }
            b.shift(answers, Timeout.TRY_ONCE, List.of(Item.keyed(request.stringAt(0), Tuple.of(-1))));
            return null;
        });
        for (int i = 1; i <= 4; i++) {
            List<Entry> answer = a.writeThenTake(requests, List.of(Item.of(Tuple.of("A", i))), answers,
                    Timeout.ofMillis(30_000), Selector.key("A"));
            assertEquals(List.of(Tuple.of(i < 4 ? i * 10L : -1)), answer);
        }
        module.get(30, TimeUnit.SECONDS);
        assertEquals(0, a.describeContainer(requests).size());
        assertEquals(0, a.describeContainer(answers).size());
        waitForConfirmations();
    }

    @Test
    void anAnswerLaterThanTheServersWaitIsStillTakenAndTheWriteHappensOnce() throws Exception {
        Future<?> late = threads.submit(() -> {
            Thread.sleep(350); // several of the server's 100 ms waits
            b.shift(answers, Timeout.TRY_ONCE, List.of(Item.keyed("A", Tuple.of(7))));
            return null;
        });
        // the answer ends the wait; the timeout only bounds a failure, with room for a busy machine
        List<Entry> answer = a.writeThenTake(requests, List.of(Item.of(Tuple.of("A", 1))), answers,
                Timeout.ofMillis(30_000), Selector.key("A"));
        assertEquals(List.of(Tuple.of(7)), answer);
        late.get(30, TimeUnit.SECONDS);
        assertEquals(List.of(Tuple.of("A", 1)), a.read(requests, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL)));
        waitForConfirmations();
    }

    @Test
    void aTakeThatTimesOutLeavesTheWriteDone() {
        for (Capi client : List.of(a, (Capi) space)) {
            ContainerRef queue = client.lookupContainer("REQUEST");
            ContainerRef keyed = client.lookupContainer("ANSWER");
            long start = System.nanoTime();
            assertThrows(SpaceTimeoutException.class, () -> client.writeThenTake(queue,
                    List.of(Item.of(Tuple.of("A", 1))), keyed, Timeout.ofMillis(250), Selector.key("A")));
            long millis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
            assertTrue(millis >= 240 && millis < 5_000, "took " + millis + " ms"); // generous: the machine may be busy
            assertEquals(List.of(Tuple.of("A", 1)), client.take(queue, Timeout.TRY_ONCE));
        }
    }

    @Test
    void aTakeThatCanNeverSucceedFailsAfterTheWrite() {
        ContainerRef plain = a.createContainer(ContainerSpec.of(Order.FIFO));
        assertThrows(robotworld.space.InvalidOperationException.class, () -> a.shiftThenTake(requests,
                List.of(Item.of(Tuple.of("A", 1))), plain, Timeout.ofMillis(1_000), Selector.key("A")));
        assertEquals(List.of(Tuple.of("A", 1)), a.take(requests, Timeout.TRY_ONCE));
    }

    @Test
    void anInterruptedCallTakesNothing() throws Exception {
        Thread caller = Thread.currentThread();
        Future<?> interrupter = threads.submit(() -> {
            Thread.sleep(300);
            caller.interrupt();
            return null;
        });
        assertThrows(SpaceInterruptedException.class, () -> a.writeThenTake(requests,
                List.of(Item.of(Tuple.of("A", 1))), answers, Timeout.INFINITE, Selector.key("A")));
        assertTrue(Thread.interrupted());
        interrupter.get(30, TimeUnit.SECONDS);
        // the take no longer waits on the server: an answer shifted now stays
        b.shift(answers, Timeout.TRY_ONCE, List.of(Item.keyed("A", Tuple.of(1))));
        Thread.sleep(100);
        assertEquals(1, a.describeContainer(answers).size());
        assertEquals(0, a.describeContainer(answers).blocked());
    }

    private void waitForConfirmations() throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (server.pendingAcknowledgements() > 0 && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        assertEquals(0, server.pendingAcknowledgements(), "every take was confirmed");
    }
}
