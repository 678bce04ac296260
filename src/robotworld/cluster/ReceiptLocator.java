package robotworld.cluster;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.function.Function;

/**
 * Finds which containers know client calls that a member has not seen (their client failed over from another
 * member), asking every container of the space in one pass for many calls at once. A pass visits every partition
 * of the cluster; right after a member dies, each of its clients settles and confirms its calls with another member
 * at the same moment, and one pass per call kept a member's serving threads busy for seconds. So callers that come
 * while a pass runs wait for the next one, which asks for all their calls together: one pass at a time, each for
 * every call that came while the one before ran.
 */
final class ReceiptLocator {

    /** The calls of the callers waiting for one pass, and the outcome they all get. */
    private static final class Pass {
        final List<String> calls = new ArrayList<>();
        final CompletableFuture<Map<String, String>> found = new CompletableFuture<>();
        boolean started;
    }

    private final Function<List<String>, Map<String, String>> askEveryContainer;
    private final Object lock = new Object();
    /** The pass callers join while another runs; null when none is waiting. */
    private Pass next;
    private boolean running;

    /** @param askEveryContainer one pass over the space's containers: call id to container id, for those found */
    ReceiptLocator(Function<List<String>, Map<String, String>> askEveryContainer) {
        this.askEveryContainer = askEveryContainer;
    }

    /**
     * Call id to container id for those of {@code calls} some container knows. A failure of the pass (the cluster
     * cannot answer in time) comes as the pass's own {@link RuntimeException}. One caller of each pass runs it.
     */
    Map<String, String> locate(Collection<String> calls) {
        Pass mine;
        boolean lead = false;
        synchronized (lock) {
            if (next == null) {
                next = new Pass();
            }
            mine = next;
            mine.calls.addAll(calls);
            try {
                while (running && !mine.started) {
                    lock.wait();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while waiting to look for calls", e);
            }
            if (!mine.started) {
                mine.started = true;
                running = true;
                next = null; // later callers gather for the pass after this one
                lead = true;
            }
        }
        if (lead) {
            try {
                mine.found.complete(askEveryContainer.apply(List.copyOf(mine.calls)));
            } catch (RuntimeException | Error e) {
                mine.found.completeExceptionally(e);
            } finally {
                synchronized (lock) {
                    running = false;
                    lock.notifyAll(); // one caller of the next pass, if any, runs it
                }
            }
        }
        try {
            return mine.found.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while looking for calls", e);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof RuntimeException failure) {
                throw failure;
            }
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(e.getCause());
        }
    }
}
