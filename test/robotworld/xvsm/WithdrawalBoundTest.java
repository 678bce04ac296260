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
    /** How late the space below says that a take's time is up, when asked to. */
    private static final long LATE_MILLIS = 400;

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
        assertCallerNotHeld(false, BOUND_MILLIS, "in the background");
    }

    @Test
    void whenTheSpaceSaysLateThatTheTimeIsUpTheCallerDoesNotWaitForTheWithdrawal() throws Exception {
        assertCallerNotHeld(true, BOUND_MILLIS + LATE_MILLIS, "slow to answer");
    }

    /**
     * A call over {@link #slowSpace} times out within {@code boundMillis}, saying {@code message}; once the space
     * lets the withdrawal go on, the request is withdrawn and nothing is left to tidy up.
     */
    private void assertCallerNotHeld(boolean lateTimeouts, long boundMillis, String message) {
        try (XVSMRuntime laptop = XVSMRuntime.using(slowSpace(lateTimeouts), "laptop", false)) {
            XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, "Bot", "Bumper");
            remote.setCallTimeout(CALL_TIMEOUT);
            ContainerRef requests = remote.requestContainer();

            long started = System.nanoTime();
            ModuleCallTimeoutException timeout = assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);
            long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);

            assertTrue(tookMillis < boundMillis, "the call took " + tookMillis + " ms");
            assertTrue(timeout.getMessage().contains(message), timeout.getMessage());
            release.countDown();
            eventually("the request is withdrawn", () -> space.describeContainer(requests).size() == 0);
            eventually("nothing is left to tidy up", () -> laptop.abandonedCalls().size() == 0);
        }
    }

    @Test
    void aRuntimeClosedWhileTheWithdrawalGoesOnStillWithdrawsTheRequest() throws Exception {
        ContainerRef requests;
        try (XVSMRuntime laptop = XVSMRuntime.using(slowSpace(false), "laptop", false)) {
            XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, "Bot", "Bumper");
            remote.setCallTimeout(CALL_TIMEOUT);
            requests = remote.requestContainer();
            assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);
        } // closing sweeps what it was left: the request is taken back even while the first withdrawal hangs
        assertEquals(0, space.describeContainer(requests).size(), "a request left for a later module host to carry out");
    }

    /**
     * The space of the tests: its first take that does not wait (the call's withdrawal) hangs until released; with
     * {@code lateTimeouts}, a take that runs out of time says so {@value #LATE_MILLIS} ms late.
     */
    private ForwardingCapi slowSpace(boolean lateTimeouts) {
        AtomicBoolean slowOnce = new AtomicBoolean(true);
        return new ForwardingCapi(space) {
            @Override
            public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
                if (timeout.equals(Timeout.TRY_ONCE)) {
                    if (slowOnce.compareAndSet(true, false)) {
                        await(release); // the call's withdrawal: the space holds it
                    }
                    return super.take(container, timeout, selectors);
                }
                try {
                    return super.take(container, timeout, selectors);
                } catch (SpaceTimeoutException e) {
                    if (lateTimeouts) {
                        sleep(LATE_MILLIS); // the timeout answer of a server busy taking partitions back
                    }
                    throw e;
                }
            }

            @Override
            public void close() {
                // the test closes the space
            }
        };
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
