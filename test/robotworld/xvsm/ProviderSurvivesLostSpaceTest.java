package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.TcpBlackhole;

/**
 * A providing program whose space becomes unreachable (not refusing: silent, or not accepting) keeps its serving
 * threads and serves again when the space returns; a caller whose space is unreachable gets its failure within
 * the call timeout plus the network allowance.
 */
@org.junit.jupiter.api.Timeout(120)
class ProviderSurvivesLostSpaceTest {

    private static final long ALLOWANCE_MILLIS = 1_000;
    /** What a busy machine may add to a bound; the bounds themselves are what is asserted against. */
    private static final long SLACK_MILLIS = 10_000;

    private EmbeddedSpace space;
    private SpaceServer server;
    private TcpBlackhole blackhole;
    private XVSMRuntime provider;
    private XVSMRuntime caller;
    private XVSMBumperModuleLocal bumper;

    @BeforeEach
    void start() throws Exception {
        space = EmbeddedSpace.open();
        server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
        blackhole = new TcpBlackhole("127.0.0.1", server.port());
        RemoteSpace.Options options = RemoteSpace.Options.defaults().networkAllowanceMillis(ALLOWANCE_MILLIS);
        provider = XVSMRuntime.using(RemoteSpace.open(URI.create("http://127.0.0.1:" + blackhole.port() + "/space"),
                options), "robot-pc", true);
        caller = XVSMRuntime.using(RemoteSpace.open(server.uri(), options), "laptop", true);
        bumper = new XVSMBumperModuleLocal(provider, "Bot", "Bumper", new FakeBumper());
    }

    @AfterEach
    void stop() throws Exception {
        caller.close();
        provider.close();
        blackhole.close();
        server.stop();
        space.close();
    }

    @Test
    void theProviderServesAgainAfterItsSpaceWasUnreachable() throws Exception {
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(caller, "Bot", "Bumper");
        remote.setCallTimeout(Duration.ofSeconds(5));
        assertEquals(0, remote.getAllBumper());

        blackhole.blackhole();
        remote.setCallTimeout(Duration.ofMillis(500));
        assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper, "nobody can serve meanwhile");
        Thread.sleep(3 * ALLOWANCE_MILLIS); // several failed takes and shifts on the provider's side
        assertTrue(bumper.isServing(), "the serving thread survived the unreachable space");

        blackhole.restore();
        remote.setCallTimeout(Duration.ofSeconds(2));
        long giveUp = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (true) {
            try {
                assertEquals(0, remote.getAllBumper());
                break;
            } catch (ModuleCallException notYet) {
                assertTrue(System.nanoTime() < giveUp, "the provider never served again: " + notYet.getMessage());
            }
        }
        assertTrue(bumper.isServing());
    }

    @Test
    void aCallWhoseSpaceIsUnreachableFailsWithinItsBound() throws Exception {
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(provider, "Bot", "Bumper");
        blackhole.blackhole();
        long callTimeout = 1_000;
        remote.setCallTimeout(Duration.ofMillis(callTimeout));
        for (int i = 0; i < 2; i++) {
            long started = System.nanoTime();
            assertThrows(ModuleCallException.class, remote::getAllBumper);
            long tookMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            assertTrue(tookMillis < callTimeout + ALLOWANCE_MILLIS + SLACK_MILLIS,
                    "bound " + (callTimeout + ALLOWANCE_MILLIS) + " ms, took " + tookMillis + " ms");
            assertFalse(Thread.currentThread().isInterrupted(), "an unreachable space is not an interrupt");
        }
    }
}
