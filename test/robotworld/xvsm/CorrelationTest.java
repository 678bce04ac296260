package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.Conditions.eventually;
import static robotworld.xvsm.XVSMWorld.BUMPER;
import static robotworld.xvsm.XVSMWorld.CONTACT_MASK;
import static robotworld.xvsm.XVSMWorld.ENVIRONMENT;
import static robotworld.xvsm.XVSMWorld.LAMP;
import static robotworld.xvsm.XVSMWorld.ROBOT;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.space.Capi;
import robotworld.space.Entry;

/**
 * A remote call only ever receives its own answer: not the late answer of an earlier call that timed out, not
 * the answer of another thread of the same host, not another host's; under load from many hosts with random
 * timeouts too.
 */
class CorrelationTest {

    private static final int HOSTS = 20;
    private static final int THREADS_PER_HOST = 4;
    private static final int CALLS_PER_THREAD = 30;

    private XVSMWorld world;

    @BeforeEach
    void start() throws Exception {
        world = XVSMWorld.start();
    }

    @AfterEach
    void stop() throws Exception {
        world.close();
    }

    @Test
    void theLateAnswerOfATimedOutCallNeverReachesTheNextCall() throws Exception {
        FakeBumper hardware = new FakeBumper().thenReturn(111, 222).hold();
        new XVSMBumperModuleLocal(world.provider(), "Fake", BUMPER, hardware);
        XVSMRuntime laptop = world.host("laptop");
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, "Fake", BUMPER);
        // the hardware holds the answer, so the call times out however long it waits: long enough that the
        // provider has taken the request by then even on a busy machine
        remote.setCallTimeout(Duration.ofSeconds(2));

        ModuleCallTimeoutException timeout = assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);
        assertTrue(timeout.getMessage().contains("was being served"), timeout.getMessage());
        assertTrue(hardware.awaitRead(0));
        hardware.release(); // the first call's answer, 111, now arrives after its caller gave up

        remote.setCallTimeout(Duration.ofSeconds(5));
        assertEquals(222, remote.getAllBumper());
        Capi space = laptop.space();
        eventually("the late answer is taken away", () -> laptop.abandonedCalls().size() == 0
                && space.describeContainer(remote.answerContainer()).size() == 0);
    }

    @Test
    void aRequestWithdrawnAfterItsTimeoutIsNeverCarriedOut() throws Exception {
        world.stopProvider();
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), "Fake", BUMPER);
        remote.setCallTimeout(Duration.ofMillis(100));
        assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);

        FakeBumper hardware = new FakeBumper().thenReturn(7);
        new XVSMBumperModuleLocal(world.startProvider(), "Fake", BUMPER, hardware);
        remote.setCallTimeout(Duration.ofSeconds(5));
        assertEquals(7, remote.getAllBumper());
        assertEquals(1, hardware.reads(), "only the second call reached the hardware");
    }

    /**
     * 20 hosts with 4 threads each call one bumper module and one lamp module, with random timeouts from 1 to
     * 400 ms (set on the host's proxies before each call: whichever thread set it last, every call runs with a
     * random timeout). Bumper answers must match the parked robot; lamp answers must repeat their own request.
     */
    @Test
    void manyHostsAndThreadsWithRandomTimeoutsNeverGetAnotherCallsAnswer() throws Exception {
        List<Thread> threads = new ArrayList<>();
        ConcurrentLinkedQueue<String> mismatches = new ConcurrentLinkedQueue<>();
        ConcurrentLinkedQueue<Throwable> unexpected = new ConcurrentLinkedQueue<>();
        AtomicInteger answered = new AtomicInteger();
        AtomicInteger timedOut = new AtomicInteger();
        AtomicInteger hardwareTimedOut = new AtomicInteger();
        CountDownLatch go = new CountDownLatch(1);
        for (int h = 0; h < HOSTS; h++) {
            XVSMRuntime host = world.host("host-" + h);
            XVSMBumperModuleRemote bumper = new XVSMBumperModuleRemote(host, ROBOT, BUMPER);
            XVSMX10LampModuleRemote lamp = new XVSMX10LampModuleRemote(host, ENVIRONMENT, LAMP);
            for (int t = 0; t < THREADS_PER_HOST; t++) {
                long seed = h * 100L + t;
                Thread thread = new Thread(() -> {
                    Random random = new Random(seed);
                    try {
                        go.await();
                        for (int i = 0; i < CALLS_PER_THREAD; i++) {
                            Duration timeout = Duration.ofMillis(1 + random.nextInt(400));
                            try {
                                if (i % 2 == 0) {
                                    bumper.setCallTimeout(timeout);
                                    callBumper(bumper, random, mismatches);
                                } else {
                                    lamp.setCallTimeout(timeout);
                                    callLamp(lamp, random, mismatches);
                                }
                                answered.incrementAndGet();
                            } catch (ModuleCallTimeoutException expected) {
                                timedOut.incrementAndGet();
                                if (expected.hardwareTimedOut()) {
                                    hardwareTimedOut.incrementAndGet();
                                }
                            }
                        }
                    } catch (Throwable e) {
                        unexpected.add(e);
                    }
                }, "caller " + h + "." + t);
                threads.add(thread);
                thread.start();
            }
        }
        go.countDown();
        for (Thread thread : threads) {
            thread.join(TimeUnit.SECONDS.toMillis(60));
        }

        System.out.printf("%d hosts x %d threads: %d calls answered, %d timed out (%d of them at the hardware), "
                + "%d mismatched%n", HOSTS, THREADS_PER_HOST, answered.get(), timedOut.get(), hardwareTimedOut.get(),
                mismatches.size());
        assertEquals(List.of(), List.copyOf(unexpected));
        assertEquals(List.of(), List.copyOf(mismatches));
        assertEquals(HOSTS * THREADS_PER_HOST * CALLS_PER_THREAD, answered.get() + timedOut.get());
        assertTrue(answered.get() > 100, "answered " + answered.get() + ", timed out " + timedOut.get());
        assertTrue(timedOut.get() > 0, "the random timeouts should make some calls give up");
        Capi space = world.provider().space();
        eventually("every late answer is taken away and no request is left", Duration.ofSeconds(10),
                () -> space.describeContainer(world.bumper.answerContainer()).size() == 0
                        && space.describeContainer(world.lamp.answerContainer()).size() == 0
                        && space.describeContainer(world.bumper.requestContainer()).size() == 0
                        && space.describeContainer(world.lamp.requestContainer()).size() == 0);
    }

    private static void callBumper(XVSMBumperModuleRemote bumper, Random random, ConcurrentLinkedQueue<String> bad) {
        if (random.nextBoolean()) {
            int mask = bumper.getAllBumper();
            if (mask != CONTACT_MASK) {
                bad.add("getAllBumper answered " + mask);
            }
        } else {
            int number = 1 + random.nextInt(8);
            boolean contact = bumper.getSingleBumper(number); // the answer names its bumper: checked inside
            if (contact != ((CONTACT_MASK >> number - 1 & 1) == 1)) {
                bad.add("getSingleBumper(" + number + ") answered " + contact);
            }
        }
    }

    /** Through {@link XVSMRemoteModule#call} to see the whole answer: it must repeat this call's own request. */
    private static void callLamp(XVSMX10LampModuleRemote lamp, Random random, ConcurrentLinkedQueue<String> bad) {
        String[] functions = {"on", "off", "dim", "brighten"};
        String function = functions[random.nextInt(functions.length)];
        int level = function.startsWith("o") ? 0 : 1 + random.nextInt(100);
        CallTuple answer = lamp.call(function, level);
        if (!answer.is(function) || !answer.fields().equals(List.of(Entry.of(level)))) {
            bad.add(function + "(" + level + ") answered " + answer);
        }
    }
}
