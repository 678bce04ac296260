package robotworld.xvsm;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.space.Item;
import robotworld.space.SpaceException;
import robotworld.space.Timeout;

/**
 * Publishes the results of local calls into the modules' ANSWER containers, in call order, on the runtime's
 * background thread. Asynchronous on purpose: a control loop reading its own bumper must not wait for the
 * space, nor stall when the space is unreachable. At most {@value #MAX_PENDING} publications wait; beyond that
 * new ones are dropped and counted (the ANSWER entry under the host's key only ever holds the latest value, so a
 * monitor catches up with the next publication).
 */
final class LocalPublisher {

    private static final Logger LOG = LoggerFactory.getLogger(LocalPublisher.class);
    static final int MAX_PENDING = 10_000;
    private static final Timeout SHIFT_TIMEOUT = Timeout.ofMillis(5_000);

    private final Executor background;
    private final AtomicInteger pending = new AtomicInteger();
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicLong failed = new AtomicLong();

    LocalPublisher(Executor background) {
        this.background = background;
    }

    /** Queues a shift of {@code answer} under its key (the own host name) into the module's ANSWER container. */
    void publish(ModuleContainers containers, CallTuple answer) {
        if (pending.incrementAndGet() > MAX_PENDING) {
            pending.decrementAndGet();
            if (dropped.incrementAndGet() % 1000 == 1) {
                LOG.warn("the space does not keep up with local calls: {} publications dropped so far", dropped.get());
            }
            return;
        }
        try {
            background.execute(() -> publishNow(containers, answer));
        } catch (RejectedExecutionException closed) {
            pending.decrementAndGet(); // the runtime has closed: nothing more goes into the space
        }
    }

    private void publishNow(ModuleContainers containers, CallTuple answer) {
        try {
            containers.onAnswers(answers -> containers.space().shift(answers, SHIFT_TIMEOUT,
                    List.of(Item.keyed(answer.key(), answer.toTuple()))));
        } catch (SpaceException e) {
            if (failed.incrementAndGet() % 1000 == 1) {
                LOG.warn("cannot publish a local call into the space ({} failures so far): {}", failed.get(),
                        e.toString());
            }
        } finally {
            pending.decrementAndGet();
        }
    }

    /** Waits until everything queued before this call has been published (or failed); false on timeout. */
    boolean awaitPublished(long millis) throws InterruptedException {
        CountDownLatch done = new CountDownLatch(1);
        try {
            background.execute(done::countDown);
        } catch (RejectedExecutionException closed) {
            return true;
        }
        return done.await(millis, TimeUnit.MILLISECONDS);
    }

    /** Publications dropped because too many were waiting. */
    long dropped() {
        return dropped.get();
    }
}
