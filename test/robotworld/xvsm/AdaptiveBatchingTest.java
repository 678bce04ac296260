package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.Conditions.async;
import static robotworld.xvsm.Conditions.eventually;
import static robotworld.xvsm.XVSMWorld.BUMPER;
import static robotworld.xvsm.XVSMWorld.CONTACT_MASK;
import static robotworld.xvsm.XVSMWorld.IR;
import static robotworld.xvsm.XVSMWorld.ROBOT;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.core.IRDistanceModule;

/**
 * Adaptive batching (thesis 6.3.1): requests that queued up while the Local side was not serving are answered
 * from one hardware read, each with the answer it would have had on its own.
 */
class AdaptiveBatchingTest {

    private static final int REQUESTS = 12;

    private XVSMWorld world;
    private XVSMRuntime laptop;
    private XVSMRuntime tablet;

    @BeforeEach
    void start() throws Exception {
        world = XVSMWorld.startWithoutProvider();
        laptop = world.host("laptop");
        tablet = world.host("tablet");
    }

    @AfterEach
    void stop() throws Exception {
        world.close();
    }

    @Test
    void waitingBumperRequestsAreAnsweredFromOneRead() throws Exception {
        CountingBumper hardware = new CountingBumper(world.bumperHardware);
        List<CompletableFuture<Boolean>> calls = queueBumperCalls();

        XVSMBumperModuleLocal local =
                new XVSMBumperModuleLocal(world.startEmptyProvider(), ROBOT, BUMPER, hardware, true);
        assertTrue(local.isAdaptiveBatching());
        for (CompletableFuture<Boolean> call : calls) {
            assertTrue(call.get(5, TimeUnit.SECONDS));
        }
        assertEquals(1, hardware.reads.get(), "one read of all bumpers for " + REQUESTS + " requests");
    }

    @Test
    void withoutBatchingEachRequestReadsTheHardware() throws Exception {
        CountingBumper hardware = new CountingBumper(world.bumperHardware);
        List<CompletableFuture<Boolean>> calls = queueBumperCalls();

        XVSMBumperModuleLocal local =
                new XVSMBumperModuleLocal(world.startEmptyProvider(), ROBOT, BUMPER, hardware, false);
        assertFalse(local.isAdaptiveBatching());
        for (CompletableFuture<Boolean> call : calls) {
            assertTrue(call.get(5, TimeUnit.SECONDS));
        }
        assertEquals(REQUESTS, hardware.reads.get());
    }

    @Test
    void batchingFollowsTheRuntimeDefaultAndCanBeSwitched() {
        XVSMRuntime provider = world.startProvider();
        assertFalse(world.bumper.isAdaptiveBatching(), "off unless asked for");
        world.bumper.setAdaptiveBatching(true);
        assertTrue(world.bumper.isAdaptiveBatching());
        provider.setAdaptiveBatchingByDefault(true);
        assertTrue(new XVSMIRDistanceModuleLocal(provider, ROBOT, "IR2", world.irHardware).isAdaptiveBatching());
    }

    @Test
    void aFailedBatchReadFailsEveryWaitingCallOnce() throws Exception {
        FakeBumper hardware = new FakeBumper();
        hardware.failWith(new IllegalStateException("bus on fire"));
        List<CompletableFuture<Boolean>> calls = queueCalls("Fake", REQUESTS);

        new XVSMBumperModuleLocal(world.startEmptyProvider(), "Fake", BUMPER, hardware, true);
        for (CompletableFuture<Boolean> call : calls) {
            ExecutionException failed = assertThrows(ExecutionException.class, () -> call.get(5, TimeUnit.SECONDS));
            assertTrue(failed.getCause() instanceof XVSMRemoteException, failed.getCause().toString());
            assertEquals("bus on fire", ((XVSMRemoteException) failed.getCause()).remoteMessage());
        }
        assertEquals(1, hardware.reads());
    }

    @Test
    void waitingIrRequestsOfEveryKindShareTwoReads() throws Exception {
        AtomicInteger reads = new AtomicInteger();
        IRDistanceModule counted = countingIr(world.irHardware, reads);
        XVSMIRDistanceModuleRemote one = new XVSMIRDistanceModuleRemote(laptop, ROBOT, IR);
        XVSMIRDistanceModuleRemote other = new XVSMIRDistanceModuleRemote(tablet, ROBOT, IR);
        CompletableFuture<String> all = async(one::getAllSensors);
        CompletableFuture<int[]> raw = async(other::getAllSensors_ByteRep);
        CompletableFuture<Integer> side = async(() -> one.getSingleSensor(2));
        CompletableFuture<Integer> cached = async(() -> other.getSingleSensor_Cached(3));
        CompletableFuture<Integer> unmounted = async(() -> other.getSingleSensor(7));
        eventually("five requests wait", () -> laptop.space().describeContainer(one.requestContainer()).size() == 5);

        new XVSMIRDistanceModuleLocal(world.startEmptyProvider(), ROBOT, IR, counted, true);
        assertEquals("0 350 350 800 800 800 800", all.get(5, TimeUnit.SECONDS));
        assertArrayEquals(world.irHardware.getAllSensors_ByteRep(), raw.get(5, TimeUnit.SECONDS));
        assertEquals(350, side.get(5, TimeUnit.SECONDS));
        assertEquals(350, cached.get(5, TimeUnit.SECONDS));
        assertEquals(800, unmounted.get(5, TimeUnit.SECONDS));
        assertEquals(2, reads.get(), "one read of the distances, one of the raw readings");
    }

    /** {@value #REQUESTS} calls from two hosts, half of them getAllBumper; waits until all are queued. */
    private List<CompletableFuture<Boolean>> queueBumperCalls() {
        return queueCalls(ROBOT, REQUESTS);
    }

    private List<CompletableFuture<Boolean>> queueCalls(String participant, int count) {
        XVSMBumperModuleRemote one = new XVSMBumperModuleRemote(laptop, participant, BUMPER);
        XVSMBumperModuleRemote other = new XVSMBumperModuleRemote(tablet, participant, BUMPER);
        List<CompletableFuture<Boolean>> calls = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            XVSMBumperModuleRemote remote = i % 2 == 0 ? one : other;
            Supplier<Boolean> call = i % 4 < 2 ? () -> remote.getAllBumper() == CONTACT_MASK
                    : () -> remote.getSingleBumper(4);
            calls.add(async(call));
        }
        eventually(count + " requests wait",
                () -> laptop.space().describeContainer(one.requestContainer()).size() >= count);
        return calls;
    }

    private static IRDistanceModule countingIr(IRDistanceModule hardware, AtomicInteger reads) {
        return new IRDistanceModule() {
            @Override
            public String getAllSensors() {
                reads.incrementAndGet();
                return hardware.getAllSensors();
            }

            @Override
            public int[] getAllSensors_ByteRep() {
                reads.incrementAndGet();
                return hardware.getAllSensors_ByteRep();
            }

            @Override
            public int getSingleSensor_Cached(int sensorNr) {
                reads.incrementAndGet();
                return hardware.getSingleSensor_Cached(sensorNr);
            }

            @Override
            public int getSingleSensor(int sensorNr) {
                reads.incrementAndGet();
                return hardware.getSingleSensor(sensorNr);
            }
        };
    }
}
