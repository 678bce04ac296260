package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;

/**
 * A module call whose space server is down (its port refuses connections) fails within its timeout plus one
 * network allowance, not two: the space's failure is the call's failure, and withdrawing the request is left to
 * the sweeper instead of being tried for another allowance. The slack left for a busy machine is smaller than one
 * allowance, so a call that spends a second one fails the test.
 */
@org.junit.jupiter.api.Timeout(120)
class ModuleCallBoundWhileSpaceDownTest {

    private static final long ALLOWANCE_MILLIS = 3_000;
    private static final long CALL_TIMEOUT_MILLIS = 2_000;
    private static final long SLACK_MILLIS = 2_000;

    @Test
    void aCallFailsWithinItsTimeoutPlusOneAllowanceWhenTheServerIsDown() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
            RemoteSpace.Options options = RemoteSpace.Options.defaults().networkAllowanceMillis(ALLOWANCE_MILLIS);
            try (XVSMRuntime caller = XVSMRuntime.using(RemoteSpace.open(server.uri(), options), "laptop", true)) {
                XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(caller, "Bot", "Bumper");
                remote.setCallTimeout(Duration.ofMillis(CALL_TIMEOUT_MILLIS));
                server.stop(); // the port now refuses connections
                for (int i = 0; i < 2; i++) {
                    long started = System.nanoTime();
                    ModuleCallException failure = assertThrows(ModuleCallException.class, remote::getAllBumper);
                    long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
                    assertTrue(tookMillis >= CALL_TIMEOUT_MILLIS, "gave up after " + tookMillis
                            + " ms, before its timeout of " + CALL_TIMEOUT_MILLIS + " ms: " + failure.getMessage());
                    assertTrue(tookMillis < CALL_TIMEOUT_MILLIS + ALLOWANCE_MILLIS + SLACK_MILLIS, "bound "
                            + (CALL_TIMEOUT_MILLIS + ALLOWANCE_MILLIS) + " ms, took " + tookMillis + " ms: "
                            + failure.getMessage());
                    assertFalse(Thread.currentThread().isInterrupted(), "a refusing server is not an interrupt");
                }
            } finally {
                server.stop();
            }
        }
    }
}
