package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.LocalTime;
import java.time.ZoneId;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.LinkPair;

/**
 * The host's timing and clock follow the reference CM11A client: quiet after each 0x55, a pause before a frame is
 * sent again after a wrong checksum, a dead interface declared after its silence, the clock in standard time.
 * Waits are checked from below only (a busy machine can make them longer, never shorter).
 */
class CM11aTimingTest {

    private static final X10Address A3 = X10Address.of('A', 3);
    /** 15 July 2026, 12:00 UTC: 14:00 summer time in Vienna, 13:00 standard time. */
    private static final Instant SUMMER_NOON_UTC = Instant.parse("2026-07-15T12:00:00Z");
    private static final ZoneId VIENNA = ZoneId.of("Europe/Vienna");

    private LinkPair pair;
    private CM11aController controller;
    private ScriptedDevice device;

    private void connect(CM11aConfig config) {
        pair = new LinkPair();
        controller = new CM11aController(pair.a(), config);
        device = new ScriptedDevice(pair.b());
    }

    @AfterEach
    void close() {
        if (controller != null) {
            controller.close();
        }
    }

    @Test
    void theDefaultsAreTheReferenceClients() {
        CM11aConfig defaults = CM11aConfig.defaults();
        assertEquals(Duration.ofSeconds(1), defaults.checksumTimeout());
        assertEquals(Duration.ofSeconds(10), defaults.readyTimeout());
        assertEquals(Duration.ofMillis(80), defaults.pauseAfterReady());
        assertEquals(Duration.ofSeconds(1), defaults.resendDelay());
        assertEquals(Duration.ofSeconds(6), defaults.deadInterfaceTimeout());
        assertEquals(Duration.ofSeconds(6), defaults.deadDeviceTimeout());
        assertEquals(6, defaults.sendsToASilentInterface());
        assertEquals(3, defaults.maxAttempts());
        assertEquals(CM11aConfig.ClockTime.STANDARD, defaults.clockTime());
    }

    @Test
    void theNextFrameWaitsAfterTheReadyByte() throws Exception {
        connect(CM11aConfig.defaults().withIdlePollInterval(Duration.ofMillis(5)));
        CompletableFuture<Void> done = CompletableFuture.runAsync(() -> controller.on(A3));
        device.expect("04 62").send("66").expect("00").send("55");
        long readyAt = System.nanoTime();
        device.expect("06 62");
        long quietMillis = (System.nanoTime() - readyAt) / 1_000_000;
        assertTrue(quietMillis >= 75, "the function frame came " + quietMillis + " ms after 0x55 (80 ms wanted)");
        device.send("68").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
    }

    @Test
    void aFrameIsSentAgainOnlyAfterThePauseThatFollowsAWrongChecksum() throws Exception {
        connect(CM11aConfig.defaults().withPauseAfterReady(Duration.ZERO).withIdlePollInterval(Duration.ofMillis(5)));
        CompletableFuture<Void> done = CompletableFuture.runAsync(() -> controller.on(A3));
        device.expect("04 62").send("67"); // wrong
        long wrongAt = System.nanoTime();
        device.expect("04 62");
        long pauseMillis = (System.nanoTime() - wrongAt) / 1_000_000;
        assertTrue(pauseMillis >= 950, "sent again " + pauseMillis + " ms after the wrong checksum (1 s wanted)");
        device.send("66").expect("00").send("55").expect("06 62").send("68").expect("00").send("55");
        done.get(30, TimeUnit.SECONDS);
    }

    @Test
    void aSilentInterfaceIsDeclaredDeadAfterItsTimeoutAndTheFrameWentOutOncePerChecksumTimeout() throws Exception {
        CM11aConfig config = CM11aConfig.defaults().withChecksumTimeout(Duration.ofMillis(150))
                .withDeadInterfaceTimeout(Duration.ofMillis(600)).withIdlePollInterval(Duration.ofMillis(5));
        connect(config);
        long start = System.nanoTime();
        X10TimeoutException e = assertThrows(X10TimeoutException.class, () -> controller.on(A3));
        long elapsedMs = (System.nanoTime() - start) / 1_000_000;
        assertTrue(elapsedMs >= 590, "declared dead after " + elapsedMs + " ms (600 ms configured)");
        assertTrue(e.getMessage().contains("4 attempts"), e.getMessage());
        assertTrue(e.getMessage().contains("said nothing for 600 ms"), e.getMessage());
        device.expect("04 62 04 62 04 62 04 62");
    }

    @Test
    void theClockIsSetInStandardTimeByDefault() {
        Clock summer = Clock.fixed(SUMMER_NOON_UTC, VIENNA);
        CM11aClock standard = CM11aClock.now(summer, CM11aConfig.ClockTime.STANDARD, HouseCode.A);
        assertEquals(LocalTime.of(13, 0), standard.time(), "CET, not CEST");
        CM11aClock legal = CM11aClock.now(summer, CM11aConfig.ClockTime.LEGAL, HouseCode.A);
        assertEquals(LocalTime.of(14, 0), legal.time());
        Clock winter = Clock.fixed(Instant.parse("2026-01-15T12:00:00Z"), VIENNA);
        assertEquals(LocalTime.of(13, 0), CM11aClock.now(winter, CM11aConfig.ClockTime.STANDARD, HouseCode.A).time());
    }

    @Test
    void aPowerFailPollIsAnsweredWithStandardTime() throws Exception {
        connect(CM11aConfig.defaults().withClock(Clock.fixed(SUMMER_NOON_UTC, VIENNA))
                .withIdlePollInterval(Duration.ofMillis(5)));
        device.send("A5");
        CM11aClock expected = CM11aClock.of(LocalDateTime.of(2026, 7, 15, 13, 0, 0), HouseCode.A);
        assertArrayEquals(expected.frame(), device.read(7), "the clock download carries 13:00:00");
        device.send(Hex.of(expected.checksum())).expect("00").send("55");
    }
}
