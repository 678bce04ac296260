package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.Conditions.async;
import static robotworld.xvsm.Conditions.eventually;
import static robotworld.xvsm.XVSMWorld.BUMPER;
import static robotworld.xvsm.XVSMWorld.CONTACT_MASK;
import static robotworld.xvsm.XVSMWorld.ROBOT;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.space.Capi;

/** Start order, restarting the Local side under load, and clean stops. */
class LifecycleTest {

    private XVSMWorld world;

    @BeforeEach
    void start() throws Exception {
        world = XVSMWorld.startWithoutProvider();
    }

    @AfterEach
    void stop() throws Exception {
        world.close();
    }

    @Test
    void aCallMadeBeforeTheLocalSideStartsIsServedOnceItDoes() throws Exception {
        XVSMRuntime laptop = world.host("laptop");
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, ROBOT, BUMPER); // creates the containers
        CompletableFuture<Integer> call = async(remote::getAllBumper);
        eventually("the request waits in the queue",
                () -> laptop.space().describeContainer(remote.requestContainer()).size() == 1);

        world.startProvider();
        assertEquals(CONTACT_MASK, call.get(5, TimeUnit.SECONDS));
    }

    @Test
    void remotesCarryOnWithALocalSideRestartedMidRun() throws Exception {
        world.startProvider();
        AtomicBoolean running = new AtomicBoolean(true);
        AtomicInteger answered = new AtomicInteger();
        AtomicInteger timedOut = new AtomicInteger();
        ConcurrentLinkedQueue<Throwable> unexpected = new ConcurrentLinkedQueue<>();
        List<Thread> callers = new ArrayList<>();
        for (String hostName : List.of("laptop", "tablet")) {
            XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host(hostName), ROBOT, BUMPER);
            remote.setCallTimeout(Duration.ofMillis(300));
            for (int t = 0; t < 2; t++) {
                Thread caller = new Thread(() -> {
                    while (running.get()) {
                        try {
                            int mask = remote.getAllBumper();
                            if (mask != CONTACT_MASK) {
                                unexpected.add(new AssertionError("answered " + mask));
                            }
                            answered.incrementAndGet();
                        } catch (ModuleCallTimeoutException e) {
                            timedOut.incrementAndGet();
                        } catch (Throwable e) {
                            unexpected.add(e);
                        }
                    }
                });
                callers.add(caller);
                caller.start();
            }
        }
        eventually("calls are answered", () -> answered.get() > 50);

        world.stopProvider();
        assertFalse(world.bumper.isServing());
        eventually("calls time out while nobody serves", () -> timedOut.get() >= 4);
        world.startProvider();
        int before = answered.get();
        eventually("the restarted Local side answers the same Remote proxies", () -> answered.get() > before + 50);

        running.set(false);
        for (Thread caller : callers) {
            caller.join(5_000);
        }
        assertEquals(List.of(), List.copyOf(unexpected));
    }

    @Test
    void bothSidesCarryOnAcrossASpaceServerRestart() {
        world.startProvider();
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), ROBOT, BUMPER);
        assertEquals(CONTACT_MASK, remote.getAllBumper());

        world.restartServer();
        remote.setCallTimeout(Duration.ofSeconds(5));
        assertEquals(CONTACT_MASK, remote.getAllBumper());
        assertTrue(world.bumper.isServing());
    }

    @Test
    void bothSidesRecoverWhenTheSpaceServerRestartsEmpty() {
        world.startProvider();
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), ROBOT, BUMPER);
        assertEquals(CONTACT_MASK, remote.getAllBumper());

        world.restartServerEmpty(); // the containers are gone; both sides create them again
        remote.setCallTimeout(Duration.ofSeconds(2));
        eventually("the Local side serves again", Duration.ofSeconds(15), () -> {
            try {
                return remote.getAllBumper() == CONTACT_MASK;
            } catch (ModuleCallException notYet) {
                return false;
            }
        });
    }

    @Test
    void closingStopsTheThreadAndLeavesNoWaitingTakeBehind() {
        world.startProvider();
        Capi space = world.provider().space();
        eventually("the Local side waits for requests",
                () -> space.describeContainer(world.bumper.requestContainer()).blocked() == 1);
        world.bumper.close();
        assertFalse(world.bumper.isServing());
        eventually("its take is withdrawn from the space",
                () -> space.describeContainer(world.bumper.requestContainer()).blocked() == 0);
        world.bumper.close(); // idempotent
        assertTrue(world.motor.isServing(), "the other modules go on");
    }

    @Test
    void closingWhileACallIsOnTheHardwareAnswersItFirst() throws Exception {
        XVSMRuntime provider = world.startProvider();
        FakeBumper hardware = new FakeBumper().thenReturn(5).hold();
        XVSMBumperModuleLocal local = new XVSMBumperModuleLocal(provider, "Fake", BUMPER, hardware);
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), "Fake", BUMPER);
        CompletableFuture<Integer> call = async(remote::getAllBumper);
        assertTrue(hardware.awaitRead(5_000));

        CompletableFuture<Object> closing = async(() -> {
            local.close();
            return null;
        });
        hardware.release();
        closing.get(5, TimeUnit.SECONDS);
        assertEquals(5, call.get(5, TimeUnit.SECONDS));
        assertFalse(local.isServing());
    }

    @Test
    void aClosedRemoteProxyRefusesCalls() {
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), ROBOT, BUMPER);
        remote.close();
        assertThrows(IllegalStateException.class, remote::getAllBumper);
    }

    @Test
    void closingTheRuntimeStopsItsModules() {
        XVSMRuntime provider = world.startProvider();
        provider.close();
        assertFalse(world.bumper.isServing());
        assertFalse(world.motor.isServing());
        assertFalse(world.lamp.isServing());
        assertTrue(provider.isClosed());
    }
}
