package robotworld.bus.interop;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.FoundModule;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.bus.modbus.DeviceIdentification;
import robotworld.bus.modbus.ServerIdReport;
import robotworld.testsupport.ProjectFiles;
import robotworld.testsupport.TestPeers;

/**
 * The master against a Modbus server we did not write: pymodbus (its RTU framer, request decoder and device
 * identity) behind a raw TCP byte stream, as a serial-over-TCP bridge offers a module (see pymodbus_peer.py).
 * It sends a multi-byte server ID, splits a long identification over two transactions, echoes N words, and can
 * answer late, trickle its bytes, or sit behind an adapter that echoes each request.
 */
class PymodbusInteropTest {

    /** A VendorName so long that pymodbus sends the ProductCode in a second transaction. */
    private static final String LONG_VENDOR = "Interop vendor " + "x".repeat(221);

    private Process peer;

    @AfterEach
    void stop() throws InterruptedException {
        if (peer != null) {
            peer.destroy();
            if (!peer.waitFor(5, TimeUnit.SECONDS)) {
                peer.destroyForcibly();
            }
        }
    }

    /** Starts the pymodbus server for a bumper module (NodeID 15B63B2) at address 2; returns its port name. */
    private String startPeer(String... options) throws IOException {
        String python = TestPeers.python("pymodbus");
        List<String> command = new ArrayList<>(List.of(python, ProjectFiles.resolve(
                "test/robotworld/bus/interop/pymodbus_peer.py").toString(), "--unit", "2", "--product", "15B63B2",
                "--vendor", LONG_VENDOR));
        command.addAll(List.of(options));
        peer = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        BufferedReader out = new BufferedReader(new InputStreamReader(peer.getInputStream(), StandardCharsets.UTF_8));
        String line = out.readLine();
        if (line == null || !line.startsWith("PORT ")) {
            throw new IOException("the pymodbus peer did not start: " + line);
        }
        return "tcp://127.0.0.1:" + line.substring(5).trim();
    }

    private static ExplorationResult explore(RS485Bus bus) throws Exception {
        return new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions"))).addresses(1, 8)
                .explore("Interop", new ExplorationListener() { });
    }

    @Test
    void aMultiByteServerIdASplitIdentificationAndAnNWordEchoAreUnderstood() throws Exception {
        try (RS485Bus bus = new RS485Bus(startPeer())) {
            ServerIdReport status = bus.reportServerId(2);
            assertTrue(status.running());
            assertEquals(LONG_VENDOR + "-15B63B2-1.0", status.serverIdText(), "pymodbus joins its identity");

            long before = bus.statistics().transactions();
            DeviceIdentification identity = bus.identify(2);
            assertEquals(2, bus.statistics().transactions() - before, "the identification came in two parts");
            assertEquals(LONG_VENDOR, identity.vendorName());
            assertEquals("15B63B2", identity.productCode());
            assertEquals("1.0", identity.revision());

            bus.echo(2, 0x0102, 0x0304, 0x0506, 0x0708, 0x090A);

            ExplorationResult result = explore(bus);
            assertEquals(List.of(2), result.modules().stream().map(FoundModule::address).toList(),
                    result.problems().toString());
            assertEquals("1.0", result.modules().get(0).version());
        }
    }

    @Test
    void aServerThatAnswersLateAndTricklesIsFound() throws Exception {
        String port = startPeer("--delay-ms", "12", "--trickle-ms", "1");
        BusTiming patientInsideAReply = new BusTiming(java.time.Duration.ofMillis(200), 3,
                java.time.Duration.ofMillis(300), java.time.Duration.ofMillis(8), BusTiming.AUTO_FRAME_GAP,
                java.time.Duration.ofSeconds(5));
        try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(115_200), patientInsideAReply)) {
            assertTrue(bus.scanReplyTimeout().toMillis() < 12, "the reply starts after the scan timeout");
            ExplorationResult result = explore(bus);
            // found; on a machine so busy that the peer stalls past every retry, reported; never lost
            java.util.Set<Integer> seen = new java.util.TreeSet<>();
            result.modules().forEach(m -> seen.add(m.address()));
            result.problems().forEach(p -> seen.add(p.address()));
            assertEquals(java.util.Set.of(2), seen, result.problems().toString());
        }
    }

    @Test
    void aServerBehindAnEchoingAdapterIsFound() throws Exception {
        // a scan allowance a busy machine cannot eat: this test is about the echo, not about a reply that comes
        // later than its probe (the Python peer may wait for a CPU)
        try (RS485Bus bus = new RS485Bus(startPeer("--echo"), SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withScanAllowance(java.time.Duration.ofMillis(500)))) {
            ExplorationResult result = explore(bus);
            assertEquals(List.of(2), result.modules().stream().map(FoundModule::address).toList(),
                    result.problems().toString());
            assertTrue(bus.echoDetected());
            bus.echo(2, 0xA502, 0x1234); // a reply equal to its request, after the request's own echo
        }
    }
}
