package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.Tuple;
import robotworld.space.remote.RemoteSpace;

/**
 * Answers a selector thread produces while it works through a round go out at the round's end: none is held back
 * past it, those of one request reach every client they complete, and answers from any other thread go out at once.
 */
@org.junit.jupiter.api.Timeout(60)
class AnswerRoundTest {

    @Test
    void anAnswerFromAThreadOutsideAnyRoundIsWrittenAtOnce() {
        List<String> written = new ArrayList<>();
        AnswerRound.write(() -> written.add("answer"));
        assertEquals(List.of("answer"), written);
    }

    @Test
    void oneWriteCompletesTheWaitsOfManyConnectionsAndEachGetsItsAnswerAtItsRoundsEnd() throws Exception {
        int before = AnswerRound.writeAtOnceUpTo;
        AnswerRound.writeAtOnceUpTo = 0; // every round defers its answers to its end, even one with one connection
        try {
            oneWriteCompletesTheWaitsOfManyConnections();
        } finally {
            AnswerRound.writeAtOnceUpTo = before;
        }
    }

    @Test
    void aRoundWithOneReadyConnectionWritesItsAnswersAtOnceAndEachGetsItsAnswer() throws Exception {
        oneWriteCompletesTheWaitsOfManyConnections();
    }

    private static void oneWriteCompletesTheWaitsOfManyConnections() throws Exception {
        int waiting = 20;
        ExecutorService threads = Executors.newCachedThreadPool();
        List<RemoteSpace> clients = new ArrayList<>();
        try (EmbeddedSpace space = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0));
             RemoteSpace writer = RemoteSpace.open(server.uri())) {
            ContainerRef box = writer.createContainer(ContainerSpec.of(Order.FIFO).withKeyView().named("BOX"));
            List<Future<List<Entry>>> takes = new ArrayList<>();
            for (int i = 0; i < waiting; i++) {
                RemoteSpace client = RemoteSpace.open(server.uri()); // a connection of its own
                clients.add(client);
                String key = "k" + i;
                takes.add(threads.submit(() -> client.take(box, Timeout.ofMillis(20_000), Selector.key(key))));
            }
            Thread.sleep(500); // the takes reach the server and wait (one that comes later finds its entry there)
            List<Item> items = new ArrayList<>();
            for (int i = 0; i < waiting; i++) {
                items.add(Item.keyed("k" + i, Tuple.of(i)));
            }
            // one request, handled on a selector thread: its write completes the waiting takes there, and their
            // answers and its own go out at the end of that thread's round
            writer.write(box, Timeout.ofMillis(5_000), items);
            for (int i = 0; i < waiting; i++) {
                assertEquals(List.of(Tuple.of(i)), takes.get(i).get(10, TimeUnit.SECONDS));
            }
        } finally {
            threads.shutdownNow();
            clients.forEach(RemoteSpace::close);
        }
    }
}
