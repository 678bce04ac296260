package robotworld.testsupport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import robotworld.explorer.cli.Rwe;

/**
 * An {@code rwe} verb that runs until stopped ({@code rwe replay --loop}, {@code rwe bridge}, {@code rwe monitor
 * --console}) running in-process on a thread of its own, as in a terminal: its output can be waited for, and
 * {@link #stop} is its Ctrl-C (the thread is interrupted, as the verbs' shutdown handling expects).
 */
public final class RunningRwe implements AutoCloseable {

    /** How long {@link #await} and {@link #awaitTrue} wait. */
    private static final long PATIENCE_SECONDS = 30;

    public final StringWriter out = new StringWriter();
    public final StringWriter err = new StringWriter();
    /** The exit code once it ended, {@link Integer#MIN_VALUE} before. */
    public final AtomicInteger exit = new AtomicInteger(Integer.MIN_VALUE);
    /** What it threw instead of returning an exit code, if anything. */
    public final AtomicReference<Throwable> failure = new AtomicReference<>();
    public final Thread thread;

    /** Starts {@code rwe args...}. */
    public RunningRwe(String... args) {
        thread = new Thread(() -> {
            try {
                exit.set(Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args));
            } catch (Throwable e) {
                failure.set(e);
            }
        }, "rwe " + args[0]);
        thread.start();
    }

    /** The first group of {@code pattern} in the output, once it is there (within 30 s, while it runs). */
    public String await(String pattern) throws InterruptedException {
        return await(Pattern.compile(pattern));
    }

    /** The first group of {@code pattern} in the output, once it is there (within 30 s, while it runs). */
    public String await(Pattern pattern) throws InterruptedException {
        String[] found = new String[1];
        awaitTrue(() -> {
            Matcher matcher = pattern.matcher(out.toString());
            found[0] = matcher.find() ? matcher.group(1) : null;
            return found[0] != null;
        }, "'" + pattern + "'");
        return found[0];
    }

    /** Waits (up to 30 s) until {@code condition} holds, while the command runs. */
    public void awaitTrue(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(PATIENCE_SECONDS);
        while (!condition.getAsBoolean()) {
            assertTrue(thread.isAlive(), "ended (" + exit + ") before " + what + ": " + this);
            assertTrue(System.nanoTime() < deadline, "not " + what + " within " + PATIENCE_SECONDS + " s: " + this);
            Thread.sleep(10);
        }
    }

    /** Stops it as Ctrl-C does in-process (its thread is interrupted); its exit code, once it ended. */
    public int stop(long withinMillis) throws InterruptedException {
        thread.interrupt();
        thread.join(withinMillis);
        assertFalse(thread.isAlive(), "still running " + withinMillis + " ms after Ctrl-C: " + this);
        assertEquals(null, failure.get());
        return exit.get();
    }

    @Override
    public void close() {
        if (thread.isAlive()) {
            thread.interrupt();
            try {
                thread.join(30_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    @Override
    public String toString() {
        return "\n--- out:\n" + out + "\n--- err:\n" + err;
    }
}
