package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.EntryType;
import robotworld.space.Item;
import robotworld.space.Notification;
import robotworld.space.Operation;
import robotworld.space.NotificationMode;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Template;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/**
 * Multi-threaded stress: producers and consumers, request/answer pairs, racing timeouts, SET races, shifts and
 * notifications under load. Each checks that nothing is lost, duplicated or reordered where order is promised.
 */
public abstract class ConcurrencyContract extends SpaceContract {

    private static final long STOP = -1;

    /**
     * How many operations a stress test makes of its {@code full} count: all of them, unless an implementation
     * whose every operation crosses several processes asks for fewer (the races are the same per operation; only
     * the suite's running time grows with the count).
     */
    protected int volume(int full) {
        return full;
    }

    @Test
    void producersAndConsumersOnABoundedQueueLoseAndDuplicateNothing() throws Exception {
        ContainerRef queue = container(ContainerSpec.of(Order.FIFO).bounded(16));
        int producers = 3;
        int consumers = 3;
        int perProducer = volume(3_000);
        List<Future<List<Long>>> consumed = new ArrayList<>();
        for (int c = 0; c < consumers; c++) {
            consumed.add(async(() -> {
                List<Long> mine = new ArrayList<>();
                while (true) {
                    long value = values(space.take(queue, Timeout.INFINITE))[0];
                    if (value == STOP) {
                        return mine;
                    }
                    mine.add(value);
                }
            }));
        }
        List<Future<?>> produced = new ArrayList<>();
        for (int p = 0; p < producers; p++) {
            long base = p * 1_000_000L;
            produced.add(async(() -> {
                for (int i = 0; i < perProducer; i++) {
                    space.write(queue, Timeout.INFINITE, num(base + i));
                }
                return null;
            }));
        }
        for (Future<?> producer : produced) {
            result(producer);
        }
        for (int c = 0; c < consumers; c++) {
            space.write(queue, Timeout.INFINITE, num(STOP));
        }
        Set<Long> all = new HashSet<>();
        int total = 0;
        for (Future<List<Long>> consumer : consumed) {
            List<Long> mine = result(consumer);
            total += mine.size();
            all.addAll(mine);
            assertProducerOrderKept(mine);
        }
        assertEquals(producers * perProducer, total, "taken in all");
        assertEquals(producers * perProducer, all.size(), "no entry taken twice");
        assertSize(queue, 0);
    }

    /** FIFO: a consumer sees each producer's entries in the order they were written. */
    private static void assertProducerOrderKept(List<Long> taken) {
        Map<Long, Long> lastByProducer = new java.util.HashMap<>();
        for (long value : taken) {
            long producer = value / 1_000_000L;
            Long last = lastByProducer.put(producer, value);
            assertTrue(last == null || last < value, "out of order: " + last + " before " + value);
        }
    }

    @Test
    void batchWritesAndBatchTakesConserveEntries() throws Exception {
        ContainerRef queue = container(ContainerSpec.of(Order.LIFO).bounded(12));
        int batches = 2 * volume(500); // even: the takers take batches * 3 / 2 pairs each
        AtomicLong taken = new AtomicLong();
        Set<Long> seen = ConcurrentHashMap.newKeySet();
        List<Future<?>> workers = new ArrayList<>();
        for (int w = 0; w < 2; w++) {
            long base = w * 1_000_000L;
            workers.add(async(() -> {
                for (int i = 0; i < batches; i++) {
                    long first = base + i * 3L;
                    space.write(queue, Timeout.INFINITE, numArray(first, first + 1, first + 2));
                }
                return null;
            }));
            workers.add(async(() -> {
                for (int i = 0; i < batches * 3 / 2; i++) {
                    for (long value : values(space.take(queue, Timeout.INFINITE, Selector.lifo(2)))) {
                        assertTrue(seen.add(value), "taken twice: " + value);
                        taken.incrementAndGet();
                    }
                }
                return null;
            }));
        }
        for (Future<?> worker : workers) {
            result(worker);
        }
        assertEquals(2L * batches * 3, taken.get());
        assertSize(queue, 0);
    }

    @Test
    void requestAnswerPairsNeverCross() throws Exception {
        ContainerRef requests = container(ContainerSpec.of(Order.FIFO).named("motorREQUEST"));
        ContainerRef answers = container(ContainerSpec.of(Order.LIFO).withKeyView().named("motorANSWER"));
        int callers = 4;
        int calls = volume(300);
        List<Future<?>> servers = new ArrayList<>();
        for (int s = 0; s < 2; s++) {
            servers.add(async(() -> {
                while (true) {
                    Tuple request = (Tuple) space.take(requests, Timeout.INFINITE).get(0);
                    if (request.arity() == 0) {
                        return null;
                    }
                    // answer under the caller's key: <argument * 2>
                    space.shift(answers, Timeout.TRY_ONCE,
                            List.of(Item.keyed(request.stringAt(0), Tuple.of(request.longAt(1) * 2))));
                }
            }));
        }
        List<Future<Integer>> clients = new ArrayList<>();
        for (int c = 0; c < callers; c++) {
            String host = "host-" + c;
            clients.add(async(() -> {
                int correct = 0;
                for (long i = 0; i < calls; i++) {
                    space.write(requests, Timeout.TRY_ONCE, Tuple.of(host, i));
                    Tuple answer = (Tuple) space.take(answers, Timeout.ofMillis(SOON.toMillis()), Selector.key(host))
                            .get(0);
                    assertEquals(i * 2, answer.longAt(0), host + " got someone else's answer");
                    correct++;
                }
                return correct;
            }));
        }
        for (Future<Integer> client : clients) {
            assertEquals(calls, result(client));
        }
        for (int s = 0; s < 2; s++) {
            space.write(requests, Timeout.TRY_ONCE, Tuple.of());
        }
        for (Future<?> server : servers) {
            result(server);
        }
        assertSize(answers, 0);
    }

    @Test
    void templateConsumersGetOnlyTheirOwnEntries() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        int kinds = 3;
        int each = volume(1_000);
        List<Future<Integer>> consumers = new ArrayList<>();
        for (int k = 0; k < kinds; k++) {
            String kind = "kind-" + k;
            consumers.add(async(() -> {
                Template mine = Template.tuple(kind, EntryType.INTEGER);
                long expected = 0;
                for (int i = 0; i < each; i++) {
                    Tuple got = (Tuple) space.take(ref, Timeout.INFINITE, Selector.template(mine)).get(0);
                    assertEquals(kind, got.stringAt(0));
                    assertEquals(expected++, got.longAt(1), "FIFO order within a kind");
                }
                return each;
            }));
        }
        for (int i = 0; i < each; i++) {
            for (int k = 0; k < kinds; k++) {
                space.write(ref, Timeout.TRY_ONCE, Tuple.of("kind-" + k, i));
            }
        }
        for (Future<Integer> consumer : consumers) {
            assertEquals(each, result(consumer));
        }
        assertSize(ref, 0);
    }

    @Test
    void takesThatTimeOutNeverSwallowEntries() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        int written = volume(5_000);
        AtomicInteger taken = new AtomicInteger();
        Set<Long> seen = ConcurrentHashMap.newKeySet();
        CyclicBarrier start = new CyclicBarrier(5);
        List<Future<?>> takers = new ArrayList<>();
        AtomicInteger writerDone = new AtomicInteger();
        for (int t = 0; t < 4; t++) {
            takers.add(async(() -> {
                start.await();
                while (writerDone.get() == 0) {
                    try {
                        for (long value : values(space.take(ref, Timeout.ofMillis(1)))) {
                            assertTrue(seen.add(value));
                            taken.incrementAndGet();
                        }
                    } catch (SpaceTimeoutException expected) {
                        // racing the writer on purpose
                    }
                }
                return null;
            }));
        }
        start.await();
        for (long i = 0; i < written; i++) {
            space.write(ref, Timeout.TRY_ONCE, num(i));
        }
        writerDone.set(1);
        for (Future<?> taker : takers) {
            result(taker);
        }
        int left = space.describeContainer(ref).size();
        assertEquals(written, taken.get() + left, "taken " + taken + " + left " + left);
    }

    @Test
    void racingWritersToASetStoreEachValueOnce() throws Exception {
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).set());
        int values = volume(1_000);
        CyclicBarrier start = new CyclicBarrier(4);
        List<Future<Integer>> writers = new ArrayList<>();
        for (int w = 0; w < 4; w++) {
            writers.add(async(() -> {
                start.await();
                int stored = 0;
                for (long i = 0; i < values; i++) {
                    try {
                        space.write(ref, Timeout.TRY_ONCE, num(i));
                        stored++;
                    } catch (SpaceTimeoutException duplicate) {
                        // someone else stored it first
                    }
                }
                return stored;
            }));
        }
        int stored = 0;
        for (Future<Integer> writer : writers) {
            stored += result(writer);
        }
        assertEquals(values, stored);
        assertSize(ref, values);
    }

    @Test
    void concurrentShiftsNeverOverfillAndConserveEntries() throws Exception {
        int capacity = 10;
        ContainerRef ref = container(ContainerSpec.of(Order.FIFO).bounded(capacity));
        int perThread = volume(2_000);
        AtomicLong displaced = new AtomicLong();
        List<Future<?>> shifters = new ArrayList<>();
        for (int t = 0; t < 3; t++) {
            long base = t * 1_000_000L;
            shifters.add(async(() -> {
                for (int i = 0; i < perThread; i++) {
                    displaced.addAndGet(space.shift(ref, Timeout.TRY_ONCE, num(base + i)).size());
                }
                return null;
            }));
        }
        for (Future<?> shifter : shifters) {
            result(shifter);
        }
        assertSize(ref, capacity);
        assertEquals(3L * perThread, displaced.get() + capacity);
    }

    @Test
    void notificationsUnderConcurrentWritesAreCompleteAndInOrder() throws Exception {
        ContainerRef ref = container(Order.FIFO);
        RecordingListener listener = RecordingListener.recording();
        space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE, Timeout.INFINITE, listener);
        int writers = 4;
        int each = volume(500);
        List<Future<?>> threads = new ArrayList<>();
        for (int w = 0; w < writers; w++) {
            long base = w * 1_000_000L;
            threads.add(async(() -> {
                for (int i = 0; i < each; i++) {
                    space.write(ref, Timeout.TRY_ONCE, num(base + i));
                }
                return null;
            }));
        }
        for (Future<?> thread : threads) {
            result(thread);
        }
        List<Notification> received = listener.awaitCount(writers * each, SOON);
        assertEquals(writers * each, received.size());
        Set<Entry> entries = new HashSet<>();
        Map<Long, Long> lastByWriter = new java.util.HashMap<>();
        for (int i = 0; i < received.size(); i++) {
            Notification notification = received.get(i);
            if (i > 0) {
                assertTrue(notification.sequence() > received.get(i - 1).sequence(), "delivered in operation order");
            }
            long value = values(notification.entries())[0];
            assertTrue(entries.add(notification.entries().get(0)), "delivered twice: " + value);
            Long last = lastByWriter.put(value / 1_000_000L, value);
            assertTrue(last == null || last < value);
        }
        // and the container agrees with the order the notifications reported
        List<Entry> stored = space.read(ref, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL));
        assertEquals(received.stream().map(n -> n.entries().get(0)).toList(), stored);
    }
}
