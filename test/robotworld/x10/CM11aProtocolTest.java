package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Clock;
import java.time.Duration;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.LinkPair;

/**
 * The host side against a device scripted byte by byte, for the cases a well-behaved simulator rarely produces
 * on its own: polls in odd places, ambiguous checksums, silence.
 */
class CM11aProtocolTest {

    private static final LocalDateTime NOW = LocalDateTime.of(2009, 3, 3, 13, 45, 30);
    /**
     * Timeouts short enough for the tests that wait them out, long enough that a busy machine answering a scripted
     * byte late does not run them out (a checksum that came too late would make the host send the frame again).
     */
    private static final CM11aConfig CONFIG = CM11aConfig.defaults()
            .withChecksumTimeout(Duration.ofSeconds(1))
            .withReadyTimeout(Duration.ofSeconds(2))
            .withIdlePollInterval(Duration.ofMillis(5))
            .withPauseAfterReady(Duration.ZERO)
            .withResendDelay(Duration.ZERO)
            .withDeadInterfaceTimeout(Duration.ofSeconds(3))
            .withClockTime(CM11aConfig.ClockTime.LEGAL)
            .withClock(Clock.fixed(NOW.toInstant(ZoneOffset.UTC), ZoneOffset.UTC));

    private LinkPair pair;
    private CM11aController controller;
    private ScriptedDevice device;
    private final BlockingQueue<X10Event> events = new LinkedBlockingQueue<>();

    @BeforeEach
    void connect() {
        pair = new LinkPair();
        controller = new CM11aController(pair.a(), CONFIG);
        controller.addListener(events::add);
        device = new ScriptedDevice(pair.b());
    }

    @AfterEach
    void close() {
        controller.close();
    }

    private CompletableFuture<Void> async(Runnable command) {
        return CompletableFuture.runAsync(command);
    }

    @Test
    void turnA3OnIsAddressThenFunctionEachWithChecksumAckAndReady() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.on(X10Address.of('A', 3)));
        device.expect("04 62").send("66").expect("00").send("55")
              .expect("06 62").send("68").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
    }

    @Test
    void wrongChecksumMeansNoAckAndTheFrameAgain() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.on(X10Address.of('A', 3)));
        device.expect("04 62").send("67")           // wrong
              .expect("04 62").send("66").expect("00").send("55")
              .expect("06 62").send("68").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
    }

    @Test
    void checksumWrongEveryTimeGivesUpAfterTheAttempts() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.on(X10Address.of('A', 3)));
        device.expect("04 62").send("67").expect("04 62").send("67").expect("04 62").send("67").expectSilence(100);
        ExecutionException e = assertThrows(ExecutionException.class, () -> done.get(30, TimeUnit.SECONDS));
        assertInstanceOf(X10ProtocolException.class, e.getCause());
        assertTrue(e.getCause().getMessage().contains("wrong checksum 67 (expected 66)"), e.getCause().getMessage());
    }

    @Test
    void pollWhereTheChecksumWasExpectedIsAnsweredThenTheFrameResent() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.on(X10Address.of('A', 3)));
        device.expect("04 62").send("5A")           // the interface polls instead of echoing
              .expect("C3").send("03 02 E9 E2")     // upload: B6 On
              .expect("04 62").send("66").expect("00").send("55")
              .expect("06 62").send("68").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
        assertEquals("B6 On", events.poll(30, TimeUnit.SECONDS).toString());
    }

    @Test
    void pollWhereReadyWasExpectedIsAnsweredThenTheFrameResent() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.on(X10Address.of('A', 3)));
        device.expect("04 62").send("66").expect("00").send("5A")
              .expect("C3").send("03 02 E9 E3")     // B6 Off
              .expect("04 62").send("66").expect("00").send("55")
              .expect("06 62").send("68").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
        assertEquals("B6 Off", events.poll(30, TimeUnit.SECONDS).toString());
    }

    @Test
    void ambiguousChecksumThatIsTheChecksum() throws Exception {
        // O Dim 2/22: 16 + 44 = 5A, the same value as a poll
        CompletableFuture<Void> done = async(() -> controller.dim(X10Address.of('O', 1), 2));
        device.expect("04 46").send("4A").expect("00").send("55")
              .expect("16 44").send("5A").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
    }

    @Test
    void ambiguousChecksumThatWasReallyAPoll() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.dim(X10Address.of('O', 1), 2));
        device.expect("04 46").send("4A").expect("00").send("55")
              .expect("16 44").send("5A")           // a poll, though the host cannot tell yet
              .expect("00").send("5A")              // the interface polls again instead of 0x55
              .expect("C3").send("03 02 E9 E2")
              .expect("16 44").send("5A").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
        assertEquals("B6 On", events.poll(30, TimeUnit.SECONDS).toString());
    }

    @Test
    void powerFailPollIsAnsweredWithTheClockBeforeTheCommandCompletes() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.on(X10Address.of('A', 3)));
        device.expect("04 62").send("A5");
        byte[] clock = device.read(7);
        assertEquals(0x9B, clock[0] & 0xFF);
        CM11aClock expected = CM11aClock.of(NOW, HouseCode.A);
        assertArrayEquals(expected.frame(), clock);
        assertTrue(!done.isDone());
        device.send(Hex.of(expected.checksum())).expect("00").send("55")
              .expect("04 62").send("66").expect("00").send("55")
              .expect("06 62").send("68").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
    }

    @Test
    void uploadWhileIdleReachesTheListener() throws Exception {
        device.send("5A").expect("C3").send("03 02 E9 E2");
        X10Event event = events.poll(30, TimeUnit.SECONDS);
        assertNotNull(event);
        assertEquals(X10Event.of(HouseCode.B, List.of(6), X10Function.ON), event);
    }

    @Test
    void powerFailWhileIdleIsAnswered() throws Exception {
        device.send("A5");
        CM11aClock expected = CM11aClock.of(NOW, HouseCode.A);
        assertArrayEquals(expected.frame(), device.read(7));
        device.send(Hex.of(expected.checksum())).expect("00").send("55");
    }

    @Test
    void powerFailPollsSentBeforeTheClockArrivedArePassedOverHoweverMany() throws Exception {
        // a host held up for a while (a busy machine, a slow bridge) finds many polls ahead of the checksum
        device.send("A5");
        CM11aClock expected = CM11aClock.of(NOW, HouseCode.A);
        assertArrayEquals(expected.frame(), device.read(7));
        device.send("A5 A5 A5 A5 A5 A5 " + Hex.of(expected.checksum())).expect("00").send("55");
        device.expectSilence(100); // the clock went out once
    }

    @Test
    void uploadPollsSentBeforeTheAcknowledgeArrivedArePassedOverHoweverMany() throws Exception {
        device.send("5A").expect("C3").send("5A 5A 5A 5A 5A 5A 03 02 E9 E2");
        X10Event event = events.poll(30, TimeUnit.SECONDS);
        assertNotNull(event);
        assertEquals(X10Event.of(HouseCode.B, List.of(6), X10Function.ON), event);
    }

    @Test
    void deadDeviceTimesOutWithinTheDocumentedTime() throws Exception {
        long start = System.nanoTime();
        X10TimeoutException e = assertThrows(X10TimeoutException.class, () -> controller.on(X10Address.of('A', 3)));
        long elapsedMs = (System.nanoTime() - start) / 1_000_000;
        long documented = CONFIG.deadDeviceTimeout().toMillis(); // 3 × 1 s
        // the upper bound leaves room for a very busy machine: it tells "gave up as documented" from "hung"
        assertTrue(elapsedMs >= documented - 10 && elapsedMs < documented + 30_000, "took " + elapsedMs + " ms");
        assertTrue(e.getMessage().contains("memory-a"), e.getMessage());
        assertTrue(e.getMessage().contains("04 62"), e.getMessage());
        device.expect("04 62 04 62 04 62"); // the frame went out once per attempt
    }

    @Test
    void missingReadyTimesOut() throws Exception {
        CompletableFuture<Void> done = async(() -> controller.on(X10Address.of('A', 3)));
        device.expect("04 62").send("66").expect("00");
        ExecutionException e = assertThrows(ExecutionException.class, () -> done.get(30, TimeUnit.SECONDS));
        assertInstanceOf(X10TimeoutException.class, e.getCause());
        assertTrue(e.getCause().getMessage().contains("0x55"), e.getCause().getMessage());
    }

    @Test
    void statusRequestReads14Bytes() throws Exception {
        CompletableFuture<CM11aStatus> status = CompletableFuture.supplyAsync(controller::requestStatus);
        device.expect("8B").send("FF FF 1E 69 06 3D 04 61 00 40 00 44 00 04");
        CM11aStatus answer = status.get(30, TimeUnit.SECONDS);
        assertEquals(0xFFFF, answer.batteryTimer());
        assertEquals(HouseCode.A, answer.monitoredHouse());
        assertEquals(java.util.Set.of(1, 3), answer.onUnits());
        assertEquals(java.util.Set.of(3), answer.dimmedUnits());
    }

    @Test
    void lostLinkFailsTheCommandAndLaterOnes() throws Exception {
        pair.b().close();
        assertThrows(X10Exception.class, () -> controller.on(X10Address.of('A', 3)));
        assertThrows(X10Exception.class, () -> controller.off(X10Address.of('A', 3)));
    }

    @Test
    void closedControllerRefusesCommands() {
        controller.close();
        X10Exception e = assertThrows(X10Exception.class, () -> controller.on(X10Address.of('A', 3)));
        assertTrue(e.getMessage().contains("closed"), e.getMessage());
    }

    @Test
    void zeroDimStepsSendNothing() throws Exception {
        controller.dim(X10Address.of('A', 1), 0);
        device.expectSilence(50);
    }
}
