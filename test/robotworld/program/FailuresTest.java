package robotworld.program;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.ConnectException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.bus.BusTimeoutException;
import robotworld.bus.InvalidPortNameException;
import robotworld.space.SpaceRequestRejectedException;
import robotworld.space.SpaceUnavailableException;
import robotworld.x10.X10TimeoutException;
import robotworld.xvsm.ModuleCallTimeoutException;

/**
 * Each operational failure, as the runtime throws it, becomes at most three lines that say what happened and name
 * the fix; never a stack frame. (The same failures, caused for real in generated programs and rwe verbs, are in
 * {@code robotworld.explorer.FailureReportsTest}.)
 */
class FailuresTest {

    private static List<String> lines(Throwable failure) {
        List<String> lines = Failures.describe(failure, "CaterpillarRobot");
        assertTrue(lines.size() >= 1 && lines.size() <= Failures.MAX_LINES, lines.toString());
        lines.forEach(line -> assertFalse(line.strip().startsWith("at "), line));
        assertTrue(lines.get(0).startsWith("CaterpillarRobot: "), lines.toString());
        return lines;
    }

    private static PortException port(String kind, String port, Exception cause) {
        return new PortException("CaterpillarRobot", kind, port, cause);
    }

    @Test
    void missingSerialPortNamesThePortProperty() {
        List<String> lines = lines(port("bus", "/dev/ttyRWE-absent",
                new IOException("/dev/ttyRWE-absent: cannot open serial port (error 2 at 356)")));
        assertEquals("CaterpillarRobot: there is no serial port /dev/ttyRWE-absent on this computer.", lines.get(0));
        assertTrue(lines.get(1).contains("-Drwe.port.CaterpillarRobot.bus=PORT"), lines.toString());
    }

    /** Whether a device that did not open is missing, forbidden or busy is told by its file, not an error number. */
    @Test
    void busyAndForbiddenPortsSayWhy(@org.junit.jupiter.api.io.TempDir java.nio.file.Path temp) throws Exception {
        String device = java.nio.file.Files.createFile(temp.resolve("ttyFAKE0")).toString();
        assertEquals("CaterpillarRobot: " + device + " is in use by another program.", lines(port("x10", device,
                new IOException(device + ": cannot open serial port (error 2 at 510)"))).get(0));
        assertTrue(lines(port("bus", temp.resolve("ttyGONE").toString(), new IOException("cannot open serial port"
                + " (error 2 at 510)"))).get(0).contains("there is no serial port"));
        if (!"root".equals(System.getProperty("user.name"))) { // root may open anything
            java.nio.file.Files.setPosixFilePermissions(temp.resolve("ttyFAKE0"), java.util.Set.of());
            assertTrue(lines(port("bus", device, new IOException(device + ": cannot open serial port (error 13 at 1)")))
                    .get(1).contains("dialout"));
        }
        assertTrue(lines(port("bus", "tcp://x", new InvalidPortNameException("'tcp://x' has no port"))).get(1)
                .contains("tcp://HOST:PORT with -Drwe.port.CaterpillarRobot.bus=PORT"));
    }

    @Test
    void refusedSimulatorPortNamesTheSimulatorAndTheProperty() {
        List<String> lines = lines(port("bus", "tcp://127.0.0.1:5020", new IOException("cannot connect",
                new ConnectException("Connection refused"))));
        assertEquals("CaterpillarRobot: nothing answers at tcp://127.0.0.1:5020 (connection refused).", lines.get(0));
        assertTrue(lines.get(1).contains("rwe simulate robot") && lines.get(1).contains("-Drwe.port.CaterpillarRobot.bus"));
        // the simulator suggested is the one on the port that was refused
        List<String> other = lines(port("x10", "tcp://127.0.0.1:6031", new IOException("cannot connect",
                new ConnectException("Connection refused"))));
        assertTrue(other.get(1).contains("rwe simulate cm11a --port tcp://127.0.0.1:6031"), other.toString());
    }

    @Test
    void silentDevicesNameTheirCheck() {
        assertTrue(lines(new BusTimeoutException("tcp://127.0.0.1:5020", 1, "MotorModule at address 1 on"
                + " tcp://127.0.0.1:5020: no reply")).get(1).contains("switched on"));
        assertTrue(lines(new X10TimeoutException("/dev/ttyS0", "no checksum")).get(1).contains("CM11A on /dev/ttyS0"));
    }

    @Test
    void spaceFailuresNameTheCommandAndTheProperty() {
        List<String> lines = lines(new SpaceUnavailableException(URI.create("http://localhost:9876/space"),
                "connection refused", null));
        assertEquals("Start it with: rwe space --port 9876, or give its address with"
                + " -Drwe.space.url=http://HOST:PORT/space.", lines.get(1));
        assertTrue(lines(new SpaceRequestRejectedException(401, "unauthorized")).get(1).contains("-Drwe.space.tokenFile"));
    }

    @Test
    void aModuleWhoseProgramDoesNotRunNamesThatProgram() {
        List<String> lines = lines(new ModuleCallTimeoutException("DimRoom", "Lamp", "on", 10_000, "no answer"));
        assertEquals("CaterpillarRobot: no answer from DimRoom's Lamp within 10000 ms: the program serving it is not"
                + " running.", lines.get(0));
        assertTrue(lines.get(1).startsWith("Start DimRoom's program"));
    }

    @Test
    void theTraceComesOnlyWithDebug() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = ParticipantMain.runReporting("Robot", () -> {
            throw new IllegalStateException("no bus port for Robot: set it in the description, -Drwe.port.Robot.bus=..."
                    + " or RWE_PORT_ROBOT_BUS");
        }, new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        assertEquals("Robot: no bus port for Robot: set it in the description, -Drwe.port.Robot.bus=... or"
                + " RWE_PORT_ROBOT_BUS\n", err.toString(StandardCharsets.UTF_8));
        System.setProperty(ParticipantMain.DEBUG_PROPERTY, "true");
        try {
            err.reset();
            ParticipantMain.runReporting("Robot", () -> {
                throw new IllegalStateException("boom");
            }, new PrintStream(err, true, StandardCharsets.UTF_8));
            assertTrue(err.toString(StandardCharsets.UTF_8).contains("\tat robotworld."), err.toString());
        } finally {
            System.clearProperty(ParticipantMain.DEBUG_PROPERTY);
        }
        assertEquals(0, ParticipantMain.runReporting("Robot", () -> { }, System.err));
    }
}
