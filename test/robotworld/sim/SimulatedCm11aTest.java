package robotworld.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.LinkClosedException;
import robotworld.x10.CM11aClock;
import robotworld.x10.CM11aStatus;
import robotworld.x10.HouseCode;
import robotworld.x10.Hex;
import robotworld.x10.X10Address;
import robotworld.x10.X10Function;

/** The simulated interface seen from a raw host: the bytes it answers, and when. */
class SimulatedCm11aTest {

    private static final X10Address A1 = X10Address.of('A', 1);
    private static final X10Address A3 = X10Address.of('A', 3);
    private static final X10Address B6 = X10Address.of('B', 6);

    private static final String DEVICES = "A1=lamp,A3=appliance,B6=appliance";

    private final SimulatedCm11a sim = SimulatedCm11a.withDevices(Cm11aTiming.fast(), DEVICES);

    @AfterEach
    void close() {
        sim.close();
    }

    @Test
    void frameGetsChecksumThenReadyAfterTheAck() throws Exception {
        try (RawHost host = new RawHost(sim.listen(0))) {
            host.send("04 62").expect("66").send("00").expect("55");
            host.send("06 62").expect("68").send("00").expect("55");
        }
        assertTrue(sim.appliance(A3).isOn());
        assertEquals(List.of("A3", "A On"), sim.powerLineLog());
    }

    @Test
    void withoutTheAckNothingIsTransmitted() throws Exception {
        // waits for the moment the interface gives up, not for a time: a busy machine may hold it back for long
        try (SimulatedCm11a impatient = SimulatedCm11a.withDevices(
                Cm11aTiming.fast().withHostTimeout(Duration.ofMillis(150)), DEVICES);
                RawHost host = new RawHost(impatient.listen(0))) {
            host.send("04 62").expect("66");
            String gaveUp = "cm11a (no 00 from the host: 04 62 not transmitted)";
            assertTrue(impatient.wire().await(lines -> lines.contains(gaveUp), Duration.ofSeconds(30)),
                    impatient.wire().lines().toString());
            assertEquals(-1, host.next(50)); // it gives up silently
            assertEquals(List.of(), impatient.powerLineLog());
            host.send("8B"); // and is idle again: a status request (which needs no 00) is answered
            CM11aStatus status = CM11aStatus.decode(host.read(14));
            assertEquals(Set.of(), status.onUnits());
            assertEquals(Set.of(), status.addressedUnits());
        }
    }

    @Test
    void aResentFrameReplacesTheUnacknowledgedOne() throws Exception {
        sim.injectBadChecksums(1);
        try (RawHost host = new RawHost(sim.listen(0))) {
            host.send("04 62").expect("67").send("04 62").expect("66").send("00").expect("55");
        }
        assertEquals(List.of("A3"), sim.powerLineLog());
    }

    @Test
    void addressingFollowsX10Rules() throws Exception {
        sim.addLamp(X10Address.of('A', 2));
        try (RawHost host = new RawHost(sim.listen(0))) {
            host.send("04 66").expect("6A").send("00").expect("55");   // A1
            host.send("04 6E").expect("72").send("00").expect("55");   // A2
            host.send("06 62").expect("68").send("00").expect("55");   // A On: both
            assertTrue(sim.lamp(A1).isOn());
            assertTrue(sim.lamp(X10Address.of('A', 2)).isOn());
            host.send("04 62").expect("66").send("00").expect("55");   // A3: a new list
            host.send("06 63").expect("69").send("00").expect("55");   // A Off: only A3
            assertTrue(sim.lamp(A1).isOn());
            assertFalse(sim.appliance(A3).isOn());
        }
    }

    @Test
    void statusRequestAnswers14BytesDescribingTheMonitoredHouse() throws Exception {
        try (RawHost host = new RawHost(sim.listen(0))) {
            host.send("04 66").expect("6A").send("00").expect("55");
            host.send("46 64").expect("AA").send("00").expect("55"); // A Dim 8/22: lamp on, dimmed
            host.send("8B");
            byte[] answer = host.read(14);
            assertEquals(14, answer.length);
            CM11aStatus status = CM11aStatus.decode(answer);
            assertEquals(0xFFFF, status.batteryTimer());
            assertEquals(HouseCode.A, status.monitoredHouse());
            assertEquals(Set.of(1), status.onUnits());
            assertEquals(Set.of(1), status.dimmedUnits());
            assertEquals(Set.of(1), status.addressedUnits());
        }
    }

    @Test
    void powerFailPollsEachIntervalIgnoringFramesUntilTheClockComes() throws Exception {
        sim.powerFail();
        try (RawHost host = new RawHost(sim.listen(0))) {
            host.expect("A5");
            host.send("04 62");                    // ignored while the interface polls
            host.expect("A5");                     // the next poll
            CM11aClock clock = CM11aClock.of(LocalDateTime.of(2009, 3, 3, 13, 45, 30), HouseCode.B);
            host.link.write(clock.frame());
            host.expectAfterPolls("A5", Hex.of(clock.checksum())).send("00").expect("55");
            host.send("04 62").expect("66").send("00").expect("55");
        }
        assertFalse(sim.isPowerFailed());
        assertEquals(HouseCode.B, sim.lastClock().orElseThrow().monitoredHouse());
        assertTrue(sim.wire().lines().contains("host 04 (ignored while polling)"), sim.wire().lines().toString());
    }

    @Test
    void uploadPollRepeatsUntilTheHostAnswers() throws Exception {
        try (RawHost host = new RawHost(sim.listen(0))) {
            sim.remoteControl(B6, X10Function.ON);
            host.expect("5A").expect("5A");        // unanswered: again after the poll interval
            host.send("C3").expectAfterPolls("5A", "03 02 E9 E2"); // a busy machine may let one more poll out
            assertEquals(-1, host.next(100));      // nothing more to upload
        }
        assertTrue(sim.appliance(B6).isOn());
    }

    @Test
    void severalMessagesShareOneUploadBuffer() throws Exception {
        sim.remoteControl(B6, X10Function.ON);
        sim.receiveFromPowerLine(A1, X10Function.DIM, 10);
        try (RawHost host = new RawHost(sim.listen(0))) {
            // B6, B On, A1, A Dim, level 10/22 of 210 = 95 (5F): mask 01010 = 0A
            host.expect("5A").send("C3").expectAfterPolls("5A", "06 0A E9 E2 66 64 5F");
        }
        assertEquals(55, sim.lamp(A1).brightnessPercent());
    }

    @Test
    void houseWideFunctionFromThePowerLine() throws Exception {
        sim.receiveFromPowerLine(A1, X10Function.ON);
        sim.receiveHouseFunction(HouseCode.A, X10Function.ALL_LIGHTS_OFF);
        assertFalse(sim.lamp(A1).isOn());
        try (RawHost host = new RawHost(sim.listen(0))) {
            host.expect("5A").send("C3").expectAfterPolls("5A", "04 06 66 62 66"); // A1, A On, A All Lights Off: mask 110
        }
    }

    @Test
    void ringControlAndEepromBlocksAreAcknowledged() throws Exception {
        try (RawHost host = new RawHost(sim.listen(0))) {
            host.send("EB").expect("EB").send("00").expect("55");
            host.send("DB").expect("DB").send("00").expect("55");
            host.send("FB 00 00 00 0C 3E 00 6D 49 00 80 00 1D 22 FF 6A 80 11 FF");
            host.expect("B8").send("00").expect("55"); // the protocol text's own example checksum
        }
    }

    @Test
    void unpluggedInterfaceSaysNothingAndAsksForTheClockWhenBack() throws Exception {
        try (RawHost host = new RawHost(sim.listen(0))) {
            sim.powerOff();
            host.send("04 62");
            assertEquals(-1, host.next(150));
            sim.powerOn();
            host.expect("A5");
        }
    }

    @Test
    void aNewConnectionTakesThePortOver() throws Exception {
        String port = sim.listen(0);
        try (RawHost first = new RawHost(port); RawHost second = new RawHost(port)) {
            second.send("04 62").expect("66").send("00").expect("55");
            assertThrows(LinkClosedException.class, () -> first.next(1_000));
        }
    }

    @Test
    void realTimingPacesTheSerialLineAndThePowerLine() throws Exception {
        Duration powerLine = Duration.ofMillis(30);
        try (SimulatedCm11a real = SimulatedCm11a.withDevices(Cm11aTiming.real(powerLine), "A3=appliance");
                RawHost host = new RawHost(real.listen(0))) {
            // 5 characters of 2.083 ms on the line (2 + 1 + 1 + 1) and one power-line transmission: never faster.
            // The upper bound only says "paced, not stalled": a busy machine may add scheduling delay (the exact
            // figures are measured by ./antw bench-x10)
            double minimum = 5 * 2.0833 + 30;
            double fastest = Double.MAX_VALUE;
            for (int i = 0; i < 3; i++) {
                long start = System.nanoTime();
                host.send("04 62").expect("66").send("00").expect("55");
                double elapsedMs = (System.nanoTime() - start) / 1e6;
                assertTrue(elapsedMs >= minimum - 0.5, "took " + elapsedMs + " ms, minimum " + minimum);
                fastest = Math.min(fastest, elapsedMs);
            }
            assertTrue(fastest < minimum + 500, "fastest of 3 took " + fastest + " ms, minimum " + minimum);
        }
    }

    @Test
    void presetDimSetsTheAddressedLampAndIsLoggedWithItsLevelNotAHouse() throws Exception {
        X10Address lamp = X10Address.of('A', 1);
        try (robotworld.x10.CM11aController controller = robotworld.x10.CM11aController.open(sim.listen(0),
                robotworld.x10.CM11aConfig.defaults().forFastSimulator())) {
            controller.presetDim(lamp, 10);
            assertEquals(Math.round(10 * 22f / 31), sim.lamp(lamp).level());
            assertTrue(sim.lamp(lamp).isOn());
            controller.presetDim(lamp, 31);
            assertEquals(22, sim.lamp(lamp).level());
            controller.presetDim(lamp, 0);
            assertFalse(sim.lamp(lamp).isOn());
        }
        List<String> log = sim.powerLineLog();
        assertTrue(log.containsAll(List.of("A1", "Preset Dim 10/31", "Preset Dim 31/31", "Preset Dim 0/31")),
                log.toString());
        assertTrue(log.stream().noneMatch(line -> line.startsWith("J ")), log.toString());
    }
}
