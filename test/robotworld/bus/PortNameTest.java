package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class PortNameTest {

    @ParameterizedTest
    @CsvSource({"/dev/ttyUSB0", "COM4", "/tmp/rwe-pty123/A", "  /dev/ttyS1  "})
    void devicePathsAreDevices(String name) {
        PortName parsed = PortName.parse(name);
        assertEquals(new PortName.Device(name.trim()), parsed);
    }

    @Test
    void tcpWithHostAndPort() {
        assertEquals(new PortName.Tcp("127.0.0.1", 5000), PortName.parse("tcp://127.0.0.1:5000"));
        assertEquals(new PortName.Tcp("cm11a.local", 4001), PortName.parse("TCP://cm11a.local:4001"));
    }

    @Test
    void tcpWithIpv6Host() {
        PortName parsed = PortName.parse("tcp://[::1]:7000");
        assertEquals(new PortName.Tcp("::1", 7000), parsed);
        assertEquals("tcp://[::1]:7000", parsed.text());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "tcp://127.0.0.1|has no port",
        "tcp://:5000|no valid host",
        "tcp://host:abc|not a number",
        "tcp://host:0|outside 1..65535",
        "tcp://host:70000|outside 1..65535",
        "tcp://::1:5000|IPv6",
        "tcp://host:5000/path|not a number",
        "udp://host:5000|unsupported port scheme 'udp'",
        "rfc2217://host:5000|unsupported port scheme",
    })
    void malformedNamesSayWhatIsWrong(String name, String expected) {
        InvalidPortNameException e = assertThrows(InvalidPortNameException.class, () -> PortName.parse(name));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }

    @Test
    void portZeroOnlyForListening() {
        assertThrows(InvalidPortNameException.class, () -> PortName.parse("tcp://127.0.0.1:0"));
        assertEquals(new PortName.Tcp("127.0.0.1", 0), PortName.parseListening("tcp://127.0.0.1:0"));
    }

    @Test
    void emptyNameIsRejected() {
        assertThrows(InvalidPortNameException.class, () -> PortName.parse(" "));
        assertThrows(InvalidPortNameException.class, () -> PortName.parse(null));
    }

    @Test
    void factoryPicksTheLinkType() {
        SerialSettings settings = SerialSettings.eightNoneOne(4800);
        assertTrue(SerialLinks.create("tcp://127.0.0.1:5000", settings) instanceof TcpSerialLink);
        assertTrue(SerialLinks.create("/dev/ttyUSB0", settings) instanceof JSerialCommLink);
        assertEquals("tcp://127.0.0.1:5000", SerialLinks.create("tcp://127.0.0.1:5000", settings).portName());
    }
}
