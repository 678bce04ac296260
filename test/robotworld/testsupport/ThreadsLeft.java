package robotworld.testsupport;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/** Whether something a test ran left threads behind: the threads of this JVM compared with those of before. */
public final class ThreadsLeft {

    private ThreadsLeft() {
    }

    /** The threads running now. */
    public static Set<Thread> now() {
        return Set.copyOf(Thread.getAllStackTraces().keySet());
    }

    /** The names of the threads started since {@code before} that still run and whose name {@code counts}. */
    public static Set<String> since(Set<Thread> before, Predicate<String> counts) {
        Set<String> names = new TreeSet<>();
        for (Thread thread : Thread.getAllStackTraces().keySet()) {
            if (thread.isAlive() && !before.contains(thread) && counts.test(thread.getName())) {
                names.add(thread.getName());
            }
        }
        return names;
    }

    /** Fails unless, within 5 s, no thread started since {@code before} whose name {@code counts} runs. */
    public static void assertNoneSince(Set<Thread> before, Predicate<String> counts) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (true) {
            Set<String> left = since(before, counts);
            if (left.isEmpty()) {
                return;
            }
            assertTrue(System.nanoTime() < deadline, "threads left running: " + left);
            Thread.sleep(50);
        }
    }
}
