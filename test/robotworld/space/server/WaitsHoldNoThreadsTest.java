package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;

/**
 * A waiting operation costs the server and the client a small object (and, over HTTP/1.1, a connection), never a
 * thread: hundreds of takes wait at once with the threads of an idle server and client, and each gets its entry.
 */
class WaitsHoldNoThreadsTest {

    private static final int WAITING = 300;

    @Test
    void hundredsOfWaitingTakesHoldNoThreadAndEachGetsItsEntry() throws Exception {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0));
             RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO));
            int serverThreadsBefore = threads("space-server");
            List<CompletableFuture<Object>> outcomes = new ArrayList<>();
            for (int i = 0; i < WAITING; i++) {
                CompletableFuture<Object> outcome = new CompletableFuture<>();
                outcomes.add(outcome);
                client.takeLater(queue, Timeout.INFINITE, new Selector[0], completion(outcome));
            }
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (client.describeContainer(queue).blocked() < WAITING && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertEquals(WAITING, client.describeContainer(queue).blocked(), "all takes wait in the space");
            int serverThreads = threads("space-server");
            int clientThreads = threads("space-client");
            // a thread per wait would add WAITING; what may be added is the pool threads Jetty starts to take the
            // burst of WAITING new connections (they end after 10 s idle), more of them on a busy machine
            assertTrue(serverThreads < serverThreadsBefore + WAITING / 3, WAITING + " waiting takes, but the server"
                    + " went from " + serverThreadsBefore + " to " + serverThreads + " threads");
            assertTrue(clientThreads <= 6, WAITING + " waiting takes, but the clients have " + clientThreads
                    + " threads");
            for (int i = 0; i < WAITING; i++) {
                client.write(queue, Timeout.TRY_ONCE, Entry.of(i));
            }
            Set<Object> received = new HashSet<>();
            for (CompletableFuture<Object> outcome : outcomes) {
                Object result = outcome.get(30, TimeUnit.SECONDS);
                assertInstanceOf(List.class, result, "a take failed: " + result);
                received.add(((List<?>) result).get(0));
            }
            assertEquals(WAITING, received.size(), "every entry went to exactly one take");
            assertEquals(0, client.describeContainer(queue).size());
        }
    }

    @Test
    void aCancelledRemoteWaitTakesNothingAndATimeoutIsReported() throws Exception {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0));
             RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO));
            CompletableFuture<Object> cancelled = new CompletableFuture<>();
            SpaceEngine.Pending pending = client.takeLater(queue, Timeout.INFINITE, new Selector[0],
                    completion(cancelled));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (client.describeContainer(queue).blocked() < 1 && System.nanoTime() < deadline) {
                Thread.sleep(5);
            }
            assertTrue(pending.cancel());
            client.write(queue, Timeout.TRY_ONCE, Entry.of(1));
            assertEquals(1, client.describeContainer(queue).size(), "the withdrawn take took nothing");
            assertEquals(0, client.describeContainer(queue).blocked());

            CompletableFuture<Object> timedOut = new CompletableFuture<>();
            ContainerRef empty = client.createContainer(ContainerSpec.of(Order.FIFO));
            long start = System.nanoTime();
            client.takeLater(empty, Timeout.ofMillis(200), new Selector[0], completion(timedOut));
            assertInstanceOf(SpaceTimeoutException.class, timedOut.get(10, TimeUnit.SECONDS));
            assertTrue(System.nanoTime() - start >= TimeUnit.MILLISECONDS.toNanos(200));
            assertTrue(!cancelled.isDone(), "a withdrawn take is never completed");
        }
    }

    private static SpaceEngine.Completion<List<robotworld.space.Entry>> completion(CompletableFuture<Object> into) {
        return new SpaceEngine.Completion<>() {
            @Override
            public void completed(List<robotworld.space.Entry> entries) {
                into.complete(entries);
            }

            @Override
            public void failed(SpaceException failure) {
                into.complete(failure);
            }
        };
    }

    private static int threads(String prefix) {
        return (int) Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().startsWith(prefix)).count();
    }
}
