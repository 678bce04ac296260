package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.Conditions.eventually;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.space.ContainerRef;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Selector;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Timeout;
import robotworld.testsupport.ForwardingCapi;

/**
 * A module call that times out withdraws its request, but that clean-up never holds the caller past the call's
 * bound: a space that is slow to withdraw (a cluster member taking its partitions back) or slow to say that the
 * time is up gets the withdrawal in the background, and the request is still never left for a module host to carry
 * out. Nobody serves the module here, so every call times out with its request still queued.
 */
class WithdrawalBoundTest {

    private static final Duration CALL_TIMEOUT = Duration.ofMillis(200);
    /** How long the slow space below holds what it is slow at: far past any bound the call may take. */
    private static final long SLOW_MILLIS = 6_000;
    /** The call's bound as asserted: its timeout, the withdrawal's wait, and what a busy machine adds. */
    private static final long BOUND_MILLIS = CALL_TIMEOUT.toMillis() + RemoteCall.WITHDRAW_MILLIS + 2_000;

    private EmbeddedSpace space;
    private final CountDownLatch release = new CountDownLatch(1);

    @BeforeEach
    void openSpace() {
        space = EmbeddedSpace.open();
    }

    @AfterEach
    void closeSpace() {
        release.countDown();
        space.close();
    }

    @Test
    void aWithdrawalTheSpaceIsSlowToMakeGoesOnWithoutTheCaller() throws Exception {
        AtomicBoolean slowOnce = new AtomicBoolean(true);
        ForwardingCapi slowToWithdraw = new ForwardingCapi(space) {
            @Override
            public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
                if (timeout.equals(Timeout.TRY_ONCE) && slowOnce.compareAndSet(true, false)) {
                    await(release); // the call's withdrawal: the space holds it
                }
                return super.take(container, timeout, selectors);
            }

            @Override
            public void close() {
                // the test closes the space
            }
        };
        try (XVSMRuntime laptop = XVSMRuntime.using(slowToWithdraw, "laptop", false)) {
            XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, "Bot", "Bumper");
            remote.setCallTimeout(CALL_TIMEOUT);
            ContainerRef requests = remote.requestContainer();

            long started = System.nanoTime();
            ModuleCallTimeoutException timeout = assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);
            long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);

            assertTrue(tookMillis < BOUND_MILLIS, "the call took " + tookMillis + " ms");
            assertTrue(timeout.getMessage().contains("in the background"), timeout.getMessage());
            assertEquals(1, space.describeContainer(requests).size(), "the withdrawal still waits on the space");
            release.countDown();
            eventually("the request is withdrawn once the space answers",
                    () -> space.describeContainer(requests).size() == 0);
            assertEquals(0, laptop.abandonedCalls().size(), "a withdrawn request leaves nothing to tidy up");
        }
    }

    @Test
    void whenTheSpaceSaysLateThatTheTimeIsUpTheSweeperWithdrawsTheRequest() throws Exception {
        ForwardingCapi lateTimeouts = new ForwardingCapi(space) {
            @Override
            public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
                if (timeout.equals(Timeout.TRY_ONCE)) {
                    return super.take(container, timeout, selectors);
                }
                try {
                    return super.take(container, timeout, selectors);
                } catch (SpaceTimeoutException e) {
                    sleep(400); // the timeout answer of a server that is busy taking partitions back
                    throw e;
                }
            }

            @Override
            public void close() {
                // the test closes the space
            }
        };
        try (XVSMRuntime laptop = XVSMRuntime.using(lateTimeouts, "laptop", false)) {
            XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, "Bot", "Bumper");
            remote.setCallTimeout(CALL_TIMEOUT);
            ContainerRef requests = remote.requestContainer();

            ModuleCallTimeoutException timeout = assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);

            assertTrue(timeout.getMessage().contains("slow to answer"), timeout.getMessage());
            eventually("the sweeper withdraws the request", () -> space.describeContainer(requests).size() == 0);
            eventually("and forgets the call", () -> laptop.abandonedCalls().size() == 0);
        }
    }

    private static void await(CountDownLatch latch) {
        try {
            if (!latch.await(SLOW_MILLIS, TimeUnit.MILLISECONDS)) {
                throw new IllegalStateException("never released");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
