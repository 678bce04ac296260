package robotworld.space;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

/** The contract of {@link SpaceEngine}'s waits without a thread, on the embedded engine. */
class WaitingWithoutThreadsTest {

    /** Records the one outcome and the thread it arrived on. */
    static final class Outcome<T> implements SpaceEngine.Completion<T> {
        final CompletableFuture<Object> result = new CompletableFuture<>();
        final AtomicInteger calls = new AtomicInteger();
        volatile Thread thread;

        @Override
        public void completed(T value) {
            calls.incrementAndGet();
            thread = Thread.currentThread();
            result.complete(value == null ? "null" : value);
        }

        @Override
        public void failed(SpaceException failure) {
            calls.incrementAndGet();
            thread = Thread.currentThread();
            result.complete(failure);
        }

        Object await() throws Exception {
            return result.get(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void anOperationPossibleAtOnceCompletesOnTheCallingThreadBeforeReturning() {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            space.write(queue, Timeout.TRY_ONCE, Entry.of(1));
            Outcome<Removal> outcome = new Outcome<>();
            assertSame(SpaceEngine.Pending.DONE, space.removeLater(queue, Operation.TAKE, Timeout.INFINITE,
                    new Selector[0], outcome));
            assertTrue(outcome.result.isDone());
            assertSame(Thread.currentThread(), outcome.thread);
            assertEquals(List.of(Entry.of(1)), ((Removal) outcome.result.join()).entries());
        }
    }

    @Test
    void aWaitingTakeIsCompletedOnTheThreadOfTheWriteThatSatisfiesIt() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            Outcome<List<Entry>> outcome = new Outcome<>();
            space.takeLater(queue, Timeout.INFINITE, new Selector[0], outcome);
            assertFalse(outcome.result.isDone());
            assertEquals(1, space.describeContainer(queue).blocked(), "it waits in the container's queue");
            Thread writer = new Thread(() -> space.write(queue, Timeout.TRY_ONCE, Entry.of(7)), "the-writer");
            writer.start();
            writer.join();
            assertEquals(List.of(Entry.of(7)), outcome.await());
            assertEquals("the-writer", outcome.thread.getName());
            assertEquals(0, space.describeContainer(queue).size(), "the waiter took it");
        }
    }

    @Test
    void aTimeoutIsReportedNeverEarly() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            Outcome<List<Entry>> outcome = new Outcome<>();
            long start = System.nanoTime();
            space.readLater(queue, Timeout.ofMillis(150), new Selector[0], outcome);
            Object result = outcome.await();
            long elapsed = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
            assertInstanceOf(SpaceTimeoutException.class, result);
            assertTrue(elapsed >= 150, "timed out after " + elapsed + " ms");
            assertEquals(0, space.describeContainer(queue).blocked());
        }
    }

    @Test
    void aCancelledWaitHasNoEffectAndIsNeverCompleted() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            Outcome<List<Entry>> outcome = new Outcome<>();
            SpaceEngine.Pending pending = space.takeLater(queue, Timeout.ofMillis(100), new Selector[0], outcome);
            assertTrue(pending.cancel());
            space.write(queue, Timeout.TRY_ONCE, Entry.of(1));
            Thread.sleep(250); // past the timeout too
            assertEquals(0, outcome.calls.get());
            assertEquals(1, space.describeContainer(queue).size(), "the entry was not taken for a withdrawn take");
            assertFalse(pending.cancel());
        }
    }

    @Test
    void aCancelAfterCompletionSaysSoAndTheResultStands() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            Outcome<List<Entry>> outcome = new Outcome<>();
            SpaceEngine.Pending pending = space.takeLater(queue, Timeout.INFINITE, new Selector[0], outcome);
            space.write(queue, Timeout.TRY_ONCE, Entry.of(1));
            assertFalse(pending.cancel());
            assertEquals(List.of(Entry.of(1)), outcome.await());
            assertEquals(1, outcome.calls.get());
        }
    }

    @Test
    void destroyingTheContainerOrClosingTheSpaceFailsTheWait() throws Exception {
        EmbeddedSpace space = EmbeddedSpace.open();
        ContainerRef destroyed = space.createContainer(ContainerSpec.of(Order.FIFO));
        ContainerRef kept = space.createContainer(ContainerSpec.of(Order.FIFO));
        Outcome<List<Entry>> first = new Outcome<>();
        Outcome<Void> second = new Outcome<>();
        space.takeLater(destroyed, Timeout.INFINITE, new Selector[0], first);
        ContainerRef small = space.createContainer(ContainerSpec.of(Order.FIFO).bounded(1));
        assertThrows(InvalidOperationException.class, () -> space.writeLater(small, Timeout.INFINITE,
                List.of(Item.of(Entry.of(1)), Item.of(Entry.of(2))), second), "known at once: thrown, not waited");
        Outcome<List<Entry>> third = new Outcome<>();
        space.readLater(kept, Timeout.INFINITE, new Selector[0], third);
        space.destroyContainer(destroyed);
        assertInstanceOf(ContainerDestroyedException.class, first.await());
        space.close();
        assertInstanceOf(SpaceClosedException.class, third.await());
        assertEquals(0, second.calls.get());
    }

    @Test
    void aWaitingWriteCompletesWhenRoomIsMadeAndWaitersAreServedOldestFirst() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef box = space.createContainer(ContainerSpec.of(Order.FIFO).bounded(1));
            space.write(box, Timeout.TRY_ONCE, Entry.of(1));
            Outcome<Void> write = new Outcome<>();
            space.writeLater(box, Timeout.INFINITE, List.of(Item.of(Entry.of(2))), write);
            assertFalse(write.result.isDone());
            assertEquals(List.of(Entry.of(1)), space.take(box, Timeout.TRY_ONCE));
            assertEquals("null", write.await());
            // a thread-less take queued before a blocking one gets the next entry first
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            Outcome<List<Entry>> older = new Outcome<>();
            space.takeLater(queue, Timeout.INFINITE, new Selector[0], older);
            CompletableFuture<List<Entry>> younger = CompletableFuture.supplyAsync(
                    () -> space.take(queue, Timeout.ofMillis(10_000)));
            while (space.describeContainer(queue).blocked() < 2) {
                Thread.sleep(1);
            }
            space.write(queue, Timeout.TRY_ONCE, Entry.of(10), Entry.of(11));
            assertEquals(List.of(Entry.of(10)), older.await());
            assertEquals(List.of(Entry.of(11)), younger.get(10, TimeUnit.SECONDS));
        }
    }

    @Test
    void aRemovalThatWaitedCanBeRestored() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO));
            Outcome<Removal> outcome = new Outcome<>();
            space.removeLater(queue, Operation.TAKE, Timeout.INFINITE, new Selector[0], outcome);
            space.write(queue, Timeout.TRY_ONCE, Entry.of(3));
            Removal removal = (Removal) outcome.await();
            assertEquals(0, space.describeContainer(queue).size());
            removal.restore();
            assertEquals(List.of(Entry.of(3)), space.read(queue, Timeout.TRY_ONCE));
        }
    }
}
