package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.fail;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.function.Supplier;
import java.util.function.BooleanSupplier;

/** Waiting for a condition instead of sleeping a fixed time. */
final class Conditions {

    private Conditions() {
    }

    /** Polls {@code condition} every few milliseconds until it holds; fails with {@code what} after {@code limit}. */
    static void eventually(String what, Duration limit, BooleanSupplier condition) {
        long deadline = System.nanoTime() + limit.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() - deadline > 0) {
                fail("not within " + limit.toMillis() + " ms: " + what);
            }
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted while waiting for: " + what);
            }
        }
    }

    /** Runs {@code call} on a thread of its own (the common pool may have a single thread on small machines). */
    static <T> CompletableFuture<T> async(Supplier<T> call) {
        return CompletableFuture.supplyAsync(call, task -> {
            Thread thread = new Thread(task, "test call");
            thread.setDaemon(true);
            thread.start();
        });
    }

    /** {@link #eventually(String, Duration, BooleanSupplier)} with twenty seconds. */
    static void eventually(String what, BooleanSupplier condition) {
        eventually(what, Duration.ofSeconds(20), condition); // only a failure waits that long
    }
}
