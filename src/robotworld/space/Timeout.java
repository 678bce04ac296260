package robotworld.space;

import java.time.Duration;

/**
 * How long an operation may wait: {@link #TRY_ONCE} (do not wait at all), a number of milliseconds, or
 * {@link #INFINITE}. When the time runs out the operation fails with {@link SpaceTimeoutException}.
 *
 * @param millis milliseconds to wait; 0 = try once; -1 = forever
 */
public record Timeout(long millis) {

    /** Do not wait: succeed at once or fail with a timeout. */
    public static final Timeout TRY_ONCE = new Timeout(0);

    /** Wait as long as it takes. */
    public static final Timeout INFINITE = new Timeout(-1);

    /** Validates the value. */
    public Timeout {
        if (millis < -1) {
            throw new IllegalArgumentException("timeout must be >= 0 ms, or -1 for infinite; was " + millis);
        }
    }

    /** Wait at most {@code millis} milliseconds. */
    public static Timeout ofMillis(long millis) {
        return new Timeout(millis);
    }

    /** Wait at most {@code duration} (rounded down to milliseconds). */
    public static Timeout of(Duration duration) {
        return new Timeout(duration.toMillis());
    }

    /**
     * What is left of {@code timeout} at this moment, for an operation that began at {@code startNanos}
     * ({@link System#nanoTime()}): infinite and try-once stay as they are; a time that has run out becomes
     * {@link #TRY_ONCE}.
     */
    public static Timeout remaining(Timeout timeout, long startNanos) {
        if (timeout.isInfinite() || timeout.isTryOnce()) {
            return timeout;
        }
        long elapsed = java.util.concurrent.TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - startNanos);
        return new Timeout(Math.max(0, timeout.millis - elapsed));
    }

    /** Whether this waits forever. */
    public boolean isInfinite() {
        return millis == -1;
    }

    /** Whether this never waits. */
    public boolean isTryOnce() {
        return millis == 0;
    }

    @Override
    public String toString() {
        return isInfinite() ? "infinite" : isTryOnce() ? "try-once" : millis + " ms";
    }
}
