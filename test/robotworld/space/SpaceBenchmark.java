package robotworld.space;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;

/**
 * Micro-benchmark of the embedded space ({@code ./antw bench-space}). Every figure is the median of several
 * timed rounds after warm-up rounds, next to a plain-JDK baseline measured in the same run, at container sizes
 * 1k, 10k and 100k so that growth with size is visible. Results vary with the machine; record them in
 * {@code docs/benchmarks.md} together with the machine they came from.
 */
public final class SpaceBenchmark {

    private static final int[] SIZES = {1_000, 10_000, 100_000};
    private static final int WARMUP_ROUNDS = 3;
    private static final int ROUNDS = 7;
    private static final Timeout NOW = Timeout.TRY_ONCE;

    /** Defeats dead-code elimination: every measured loop feeds it. */
    private static long sink;

    private SpaceBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        long started = System.nanoTime();
        System.out.printf(Locale.ROOT, "Space benchmark: Java %s, %d cores, medians of %d rounds after %d warm-up%n%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(), ROUNDS, WARMUP_ROUNDS);
        warmUp();
        header();
        double fifo1k = 0;
        for (int size : SIZES) {
            double space = fifoPair(size);
            double base = dequePair(size);
            row("FIFO write+take (1 thread)", size, space, base, "ArrayDeque offer+poll");
            fifo1k = size == SIZES[0] ? space : fifo1k;
        }
        Map<Integer, Double> key = new HashMap<>();
        for (int size : SIZES) {
            key.put(size, keyShiftTake(size));
            row("KEY shift+take", size, key.get(size), hashMapPair(size), "HashMap put+remove");
        }
        Map<Integer, Double> vector = new HashMap<>();
        for (int size : SIZES) {
            vector.put(size, vectorTakeWrite(size));
            row("VECTOR take+write at position", size, vector.get(size), arrayListSlot(size), "ArrayList set+set");
        }
        for (int size : SIZES) {
            row("template read, match at the end", size, templateRead(size), listScan(size), "ArrayList scan");
        }
        System.out.println();
        notifications();
        System.out.println();
        System.out.printf(Locale.ROOT, "FIFO pair at 1k entries: %.0f ns (target <= 1000 ns): %s%n", fifo1k,
                fifo1k <= 1000 ? "met" : "NOT met");
        System.out.printf(Locale.ROOT, "KEY cost 100k/1k: %.2fx; VECTOR cost 100k/1k: %.2fx (1.0 = independent of size)%n",
                key.get(100_000) / key.get(1_000), vector.get(100_000) / vector.get(1_000));
        System.out.printf(Locale.ROOT, "total time %.1f s (checksum %d)%n",
                (System.nanoTime() - started) / 1e9, sink);
    }

    /** One discarded pass over every space measurement, so that the first rows are not paying for the JIT. */
    private static void warmUp() {
        sink += (long) (fifoPair(1_000) + keyShiftTake(1_000) + vectorTakeWrite(1_000) + templateRead(1_000));
    }

    // ---- space measurements: each returns median ns per operation (pair) ----

    private static double fifoPair(int size) {
        try (Capi space = EmbeddedSpace.open()) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
            prefill(space, ref, size);
            Entry entry = Entry.of(42);
            int ops = 500_000;
            return median(ops, () -> {
                long sum = 0;
                for (int i = 0; i < ops; i++) {
                    space.write(ref, NOW, entry);
                    sum += space.take(ref, NOW).size();
                }
                return sum;
            });
        }
    }

    private static double keyShiftTake(int size) {
        try (Capi space = EmbeddedSpace.open()) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.LIFO).withKeyView());
            List<Item> fill = new ArrayList<>();
            for (int i = 0; i < size; i++) {
                fill.add(Item.keyed("resident-" + i, Entry.of(i)));
            }
            space.write(ref, NOW, fill);
            int distinct = 1024;
            List<List<Item>> shifts = new ArrayList<>();
            Selector[] takes = new Selector[distinct];
            for (int i = 0; i < distinct; i++) {
                shifts.add(List.of(Item.keyed("host-" + i, Tuple.of("answer", i))));
                takes[i] = Selector.key("host-" + i);
            }
            int ops = 300_000;
            return median(ops, () -> {
                long sum = 0;
                for (int i = 0; i < ops; i++) {
                    int k = i & (distinct - 1);
                    sum += space.shift(ref, NOW, shifts.get(k)).size();
                    sum += space.take(ref, NOW, takes[k]).size();
                }
                return sum;
            });
        }
    }

    private static double vectorTakeWrite(int size) {
        try (Capi space = EmbeddedSpace.open()) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO).withVectorView());
            prefill(space, ref, size);
            int distinct = 1024;
            Selector[] takes = new Selector[distinct];
            List<List<Item>> writes = new ArrayList<>();
            int stride = size / distinct; // spread the positions over the whole vector
            for (int i = 0; i < distinct; i++) {
                int position = Math.min(size - 1, i * Math.max(1, stride));
                takes[i] = Selector.vector(position);
                writes.add(List.of(Item.at(position, Entry.of(position))));
            }
            int ops = 300_000;
            return median(ops, () -> {
                long sum = 0;
                for (int i = 0; i < ops; i++) {
                    int k = i & (distinct - 1);
                    sum += space.take(ref, NOW, takes[k]).size();
                    space.write(ref, NOW, writes.get(k));
                }
                return sum;
            });
        }
    }

    private static double templateRead(int size) {
        try (Capi space = EmbeddedSpace.open()) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
            List<Item> fill = new ArrayList<>();
            for (int i = 0; i < size; i++) {
                fill.add(Item.of(Tuple.of("robot-" + (i % 10), i, "payload")));
            }
            space.write(ref, NOW, fill);
            // only the newest entry matches, so every read scans the whole container
            Selector last = Selector.template(Template.tuple(EntryType.STRING, size - 1, Template.ANY));
            int ops = Math.max(20, 2_000_000 / size);
            return median(ops, () -> {
                long sum = 0;
                for (int i = 0; i < ops; i++) {
                    sum += space.read(ref, NOW, last).size();
                }
                return sum;
            });
        }
    }

    private static void prefill(Capi space, ContainerRef ref, int size) {
        Entry[] entries = new Entry[size];
        for (int i = 0; i < size; i++) {
            entries[i] = Entry.of(i);
        }
        space.write(ref, NOW, entries);
    }

    // ---- baselines ----

    private static double dequePair(int size) {
        ArrayDeque<Entry> deque = new ArrayDeque<>();
        for (int i = 0; i < size; i++) {
            deque.add(Entry.of(i));
        }
        Entry entry = Entry.of(42);
        int ops = 500_000;
        return median(ops, () -> {
            long sum = 0;
            for (int i = 0; i < ops; i++) {
                deque.offer(entry);
                sum += deque.poll().hashCode();
            }
            return sum;
        });
    }

    private static double hashMapPair(int size) {
        Map<String, Entry> map = new HashMap<>();
        for (int i = 0; i < size; i++) {
            map.put("resident-" + i, Entry.of(i));
        }
        int distinct = 1024;
        String[] keys = new String[distinct];
        for (int i = 0; i < distinct; i++) {
            keys[i] = "host-" + i;
        }
        Entry entry = Entry.of(42);
        int ops = 300_000;
        return median(ops, () -> {
            long sum = 0;
            for (int i = 0; i < ops; i++) {
                String key = keys[i & (distinct - 1)];
                map.put(key, entry);
                sum += map.remove(key).hashCode();
            }
            return sum;
        });
    }

    private static double arrayListSlot(int size) {
        List<Entry> slots = new ArrayList<>();
        for (int i = 0; i < size; i++) {
            slots.add(Entry.of(i));
        }
        int stride = Math.max(1, size / 1024);
        int ops = 300_000;
        return median(ops, () -> {
            long sum = 0;
            for (int i = 0; i < ops; i++) {
                int position = Math.min(size - 1, (i & 1023) * stride);
                Entry old = slots.set(position, null);
                slots.set(position, old);
                sum += old.hashCode();
            }
            return sum;
        });
    }

    private static double listScan(int size) {
        List<Tuple> list = new ArrayList<>();
        for (int i = 0; i < size; i++) {
            list.add(Tuple.of("robot-" + (i % 10), i, "payload"));
        }
        Template last = Template.tuple(EntryType.STRING, size - 1, Template.ANY);
        int ops = Math.max(20, 2_000_000 / size);
        return median(ops, () -> {
            long sum = 0;
            for (int i = 0; i < ops; i++) {
                for (Tuple tuple : list) {
                    if (last.matches(tuple)) {
                        sum++;
                        break;
                    }
                }
            }
            return sum;
        });
    }

    // ---- notifications ----

    private static void notifications() throws InterruptedException {
        int events = 200_000;
        for (int subscribers : new int[] {1, 4}) {
            double[] rates = new double[ROUNDS];
            for (int round = -WARMUP_ROUNDS; round < ROUNDS; round++) {
                double rate = notificationRate(events, subscribers);
                if (round >= 0) {
                    rates[round] = rate;
                }
            }
            System.out.printf(Locale.ROOT, "notification delivery, %d subscriber(s): %,.0f notifications/s "
                    + "(write+take per event, %,d events/round)%n", subscribers, median(rates), events);
        }
        double[] baseline = new double[ROUNDS];
        for (int round = -WARMUP_ROUNDS; round < ROUNDS; round++) {
            double rate = handOffRate(events);
            if (round >= 0) {
                baseline[round] = rate;
            }
        }
        System.out.printf(Locale.ROOT, "baseline LinkedBlockingQueue hand-off to one thread: %,.0f items/s%n",
                median(baseline));
    }

    /** Writes {@code events} entries (each taken again) and returns notifications delivered per second. */
    private static double notificationRate(int events, int subscribers) throws InterruptedException {
        try (Capi space = EmbeddedSpace.open(events + 1)) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
            CountDownLatch delivered = new CountDownLatch(subscribers);
            AtomicLong received = new AtomicLong();
            for (int s = 0; s < subscribers; s++) {
                space.subscribe(ref, EnumSet.of(Operation.WRITE), NotificationMode.INFINITE, Timeout.INFINITE,
                        new CountingListener(events, received, delivered));
            }
            Entry entry = Entry.of(1);
            long start = System.nanoTime();
            for (int i = 0; i < events; i++) {
                space.write(ref, NOW, entry);
                space.take(ref, NOW);
            }
            if (!delivered.await(60, TimeUnit.SECONDS)) {
                throw new IllegalStateException("notifications missing: " + received.get());
            }
            return (double) events * subscribers / ((System.nanoTime() - start) / 1e9);
        }
    }

    private static double handOffRate(int items) throws InterruptedException {
        LinkedBlockingQueue<Entry> queue = new LinkedBlockingQueue<>();
        CountDownLatch done = new CountDownLatch(1);
        Thread consumer = new Thread(() -> {
            try {
                for (int i = 0; i < items; i++) {
                    sink += queue.take().hashCode() & 1;
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            done.countDown();
        });
        consumer.start();
        Entry entry = Entry.of(1);
        long start = System.nanoTime();
        for (int i = 0; i < items; i++) {
            queue.add(entry);
        }
        done.await();
        return items / ((System.nanoTime() - start) / 1e9);
    }

    /** Counts deliveries and opens its latch when all expected ones have arrived. */
    private static final class CountingListener implements NotificationListener {
        private final int expected;
        private final AtomicLong total;
        private final CountDownLatch done;
        private int count;

        CountingListener(int expected, AtomicLong total, CountDownLatch done) {
            this.expected = expected;
            this.total = total;
            this.done = done;
        }

        @Override
        public void onNotification(Notification notification) {
            total.incrementAndGet();
            if (++count == expected) {
                done.countDown();
            }
        }
    }

    // ---- timing and printing ----

    /** Runs {@code body} (doing {@code ops} operations) for warm-up and timed rounds; median ns per operation. */
    private static double median(int ops, LongSupplier body) {
        double[] nanosPerOp = new double[ROUNDS];
        for (int round = -WARMUP_ROUNDS; round < ROUNDS; round++) {
            long start = System.nanoTime();
            sink += body.getAsLong();
            long elapsed = System.nanoTime() - start;
            if (round >= 0) {
                nanosPerOp[round] = (double) elapsed / ops;
            }
        }
        return median(nanosPerOp);
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    private static void header() {
        System.out.printf(Locale.ROOT, "%-34s %8s %12s %14s %12s %8s  %s%n", "operation", "entries", "ns/op",
                "ops/s", "baseline ns", "ratio", "baseline");
    }

    private static void row(String what, int size, double nanos, double baselineNanos, String baseline) {
        System.out.printf(Locale.ROOT, "%-34s %8d %12.1f %,14.0f %12.1f %7.1fx  %s%n", what, size, nanos,
                1e9 / nanos, baselineNanos, nanos / baselineNanos, baseline);
    }
}
