package robotworld.cluster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** Many members' worth of calls to look for after a failover: one pass over the containers for many callers. */
@org.junit.jupiter.api.Timeout(60)
class ReceiptLocatorTest {

    /** A pass that finds every call whose id ends in an even digit, in container "c-" + id. */
    private static Map<String, String> evenOnes(List<String> calls) {
        Map<String, String> found = new HashMap<>();
        for (String call : calls) {
            if ((call.charAt(call.length() - 1) - '0') % 2 == 0) {
                found.put(call, "c-" + call);
            }
        }
        return found;
    }

    @Test
    void callersThatComeWhileAPassRunsShareTheNextOne() throws Exception {
        AtomicInteger passes = new AtomicInteger();
        CountDownLatch firstPassMayEnd = new CountDownLatch(1);
        ReceiptLocator locator = new ReceiptLocator(calls -> {
            if (passes.incrementAndGet() == 1) {
                try {
                    firstPassMayEnd.await();
                } catch (InterruptedException e) {
                    throw new IllegalStateException(e);
                }
            }
            return evenOnes(calls);
        });
        ExecutorService threads = Executors.newCachedThreadPool();
        try {
            Future<Map<String, String>> first = threads.submit(() -> locator.locate(List.of("call-0")));
            while (passes.get() == 0) {
                Thread.sleep(1);
            }
            List<Future<Map<String, String>>> others = new ArrayList<>();
            for (int i = 1; i <= 30; i++) {
                String call = "call-" + i;
                others.add(threads.submit(() -> locator.locate(List.of(call))));
            }
            Thread.sleep(300); // they gather behind the running pass
            firstPassMayEnd.countDown();
            assertEquals(Map.of("call-0", "c-call-0"), first.get(10, TimeUnit.SECONDS));
            for (int i = 1; i <= 30; i++) {
                Map<String, String> found = others.get(i - 1).get(10, TimeUnit.SECONDS);
                String call = "call-" + i;
                assertEquals(i % 2 == 0 ? "c-" + call : null, found.get(call), "the answer for " + call);
            }
            // one pass for the first caller, and (on a machine so busy that some came late) very few for the 30
            assertTrue(passes.get() <= 4, "passes: " + passes.get() + " for 31 callers");
        } finally {
            threads.shutdownNow();
        }
    }

    @Test
    void aFailedPassFailsItsCallersAndTheNextPassRunsAnyway() {
        AtomicInteger passes = new AtomicInteger();
        IllegalStateException unavailable = new IllegalStateException("the cluster did not answer in time");
        ReceiptLocator locator = new ReceiptLocator(calls -> {
            if (passes.incrementAndGet() == 1) {
                throw unavailable;
            }
            return evenOnes(calls);
        });
        assertSame(unavailable, assertThrows(IllegalStateException.class, () -> locator.locate(List.of("call-2"))));
        assertEquals(Map.of("call-2", "c-call-2"), locator.locate(List.of("call-2", "call-3")));
    }
}
