package robotworld.cluster;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Notification;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/**
 * A cluster member in a process of its own, driven line by line on its standard input, so that tests can run
 * members where the test itself cannot reach them (another network namespace) and kill them for real. Prints
 * {@code ready <host:port>}, then one line per command: {@code ok ...} or {@code error <exception> <message>}.
 *
 * <pre>
 * members                      -> ok 3
 * create NAME                  -> ok            (a FIFO container, looked up or created)
 * write NAME 1 2 3             -> ok            (try once)
 * take NAME COUNT MILLIS       -> ok 1 2 ...    (the COUNT oldest)
 * size NAME                    -> ok 5
 * subscribe NAME               -> ok            (counts WRITE notifications)
 * notified NAME                -> ok 17 none    (count, and how the subscription ended)
 * quit
 * </pre>
 *
 * Arguments: {@code CLUSTER BIND_ADDRESS PORT MINIMUM_MEMBERS MEMBER...}.
 */
public final class ScriptedMember {

    private ScriptedMember() {
    }

    public static void main(String[] args) throws Exception {
        PrintStream out = new PrintStream(System.out, true, StandardCharsets.UTF_8);
        ClusterOptions options = ClusterOptions.named(args[0]).withBindAddress(args[1])
                .withPort(Integer.parseInt(args[2])).withMinimumMembers(Integer.parseInt(args[3]))
                .withMembers(Arrays.asList(args).subList(4, args.length))
                .withFailureDetection(Duration.ofSeconds(3));
        Map<String, Counter> counters = new ConcurrentHashMap<>();
        try (ClusterMember member = ClusterMember.start(options)) {
            ClusterSpace space = member.openSpace(ClusterMember.DEFAULT_SPACE);
            out.println("ready " + member.address());
            BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
            String line;
            while ((line = in.readLine()) != null && !line.equals("quit")) {
                String[] words = line.trim().split("\\s+");
                try {
                    out.println("ok" + run(member, space, counters, words));
                } catch (RuntimeException e) {
                    out.println("error " + e.getClass().getSimpleName() + " "
                            + String.valueOf(e.getMessage()).replace('\n', ' '));
                }
            }
        }
        System.exit(0);
    }

    private static String run(ClusterMember member, ClusterSpace space, Map<String, Counter> counters,
                              String[] words) {
        switch (words[0]) {
            case "members":
                return " " + member.memberCount();
            case "create":
                space.lookupOrCreateContainer(ContainerSpec.of(Order.FIFO).named(words[1]));
                return "";
            case "write": {
                ContainerRef ref = space.lookupContainer(words[1]);
                List<Entry> entries = new ArrayList<>();
                for (int i = 2; i < words.length; i++) {
                    entries.add(Entry.of(Long.parseLong(words[i])));
                }
                space.write(ref, Timeout.TRY_ONCE, entries.toArray(new Entry[0]));
                return "";
            }
            case "take": {
                ContainerRef ref = space.lookupContainer(words[1]);
                List<Entry> taken = space.take(ref, Timeout.ofMillis(Long.parseLong(words[3])),
                        Selector.fifo(Integer.parseInt(words[2])));
                StringBuilder values = new StringBuilder();
                for (Entry entry : taken) {
                    values.append(' ').append(((IntEntry) entry).value());
                }
                return values.toString();
            }
            case "size":
                return " " + space.describeContainer(space.lookupContainer(words[1])).size();
            case "subscribe": {
                Counter counter = new Counter();
                space.subscribe(space.lookupContainer(words[1]), EnumSet.of(Operation.WRITE),
                        NotificationMode.INFINITE, Timeout.INFINITE, counter);
                counters.put(words[1], counter);
                return "";
            }
            case "notified": {
                Counter counter = counters.get(words[1]);
                SubscriptionEnd end = counter.end.get();
                return " " + counter.count.get() + " " + (end == null ? "none" : end.name());
            }
            default:
                throw new IllegalArgumentException("unknown command " + words[0]);
        }
    }

    private static final class Counter implements NotificationListener {
        final AtomicInteger count = new AtomicInteger();
        final AtomicReference<SubscriptionEnd> end = new AtomicReference<>();

        @Override
        public void onNotification(Notification notification) {
            count.addAndGet(notification.entries().size());
        }

        @Override
        public void onEnd(SubscriptionEnd reason) {
            end.set(reason);
        }
    }
}
