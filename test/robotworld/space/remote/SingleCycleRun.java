package robotworld.space.remote;

import java.net.URI;
import java.util.Arrays;
import java.util.List;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.Tuple;
import robotworld.space.server.SpaceServer;

/**
 * The module-call cycle of one pair ({@code writeThenTake} / {@code shiftThenTake}) against a server in this JVM,
 * for comparing two builds of the client and server: run it alternately with each build's classes first on the
 * class path, under {@code taskset -c 0} (see {@code docs/benchmarks.md}). Prints the p50 of each round after a
 * warm-up round of 20 000 cycles. Arguments: rounds (including the warm-up), a label. {@code -Dcycle.binary=false}:
 * the bodies as JSON.
 */
public final class SingleCycleRun {

    private SingleCycleRun() {
    }

    public static void main(String[] args) throws Exception {
        int rounds = Integer.parseInt(args[0]);
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0))) {
            StringBuilder medians = new StringBuilder();
            for (int round = 0; round < rounds; round++) {
                long[] samples = cycles(server.uri(), round == 0 ? 20_000 : 3_000);
                Arrays.sort(samples);
                if (round > 0) {
                    medians.append(String.format(" %.1f", samples[samples.length / 2] / 1e3));
                }
                if (Boolean.getBoolean("cycle.trace")) { // each round's p50 and when it ended, for a profile's time line
                    System.err.printf("%d %.1f%n", System.currentTimeMillis(), samples[samples.length / 2] / 1e3);
                }
            }
            System.out.println(args[1] + " p50 us:" + medians);
        }
    }

    private static long[] cycles(URI uri, int count) throws Exception {
        RemoteSpace.Options options = RemoteSpace.Options.defaults()
                .binary(Boolean.parseBoolean(System.getProperty("cycle.binary", "true")));
        try (RemoteSpace a = RemoteSpace.open(uri, options); RemoteSpace b = RemoteSpace.open(uri, options)) {
            String suffix = Long.toString(System.nanoTime());
            ContainerRef requests = a.createContainer(ContainerSpec.of(Order.FIFO).named("REQUEST" + suffix));
            ContainerRef answers = a.createContainer(ContainerSpec.of(Order.LIFO).withKeyView().named("ANSWER"
                    + suffix));
            Thread module = new Thread(() -> {
                Tuple request = (Tuple) b.take(requests, Timeout.INFINITE).get(0);
                while (request.arity() != 0) {
                    List<Item> answer = List.of(Item.keyed(request.stringAt(0), Tuple.of(request.longAt(1) + 1)));
                    request = (Tuple) b.shiftThenTake(answers, answer, requests, Timeout.INFINITE).get(0);
                }
            }, "cycle-module");
            module.start();
            long[] samples = new long[count];
            for (int i = 0; i < count; i++) {
                long start = System.nanoTime();
                Tuple answer = (Tuple) a.writeThenTake(requests, List.of(Item.of(Tuple.of("A", i))), answers,
                        Timeout.ofMillis(5_000), Selector.key("A")).get(0);
                samples[i] = System.nanoTime() - start;
                if (answer.longAt(0) != i + 1) {
                    throw new IllegalStateException("wrong answer " + answer + " for " + i);
                }
            }
            a.write(requests, Timeout.TRY_ONCE, Tuple.of());
            module.join();
            return samples;
        }
    }
}
