package robotworld.bus;

import java.io.IOException;

/** Makes the right {@link SerialLink} for a port name: jSerialComm for devices, TCP for {@code tcp://}. */
public final class SerialLinks {

    private SerialLinks() {
    }

    /**
     * Creates a link for {@code portName} without opening it.
     *
     * @throws InvalidPortNameException when the name is malformed
     */
    public static SerialLink create(String portName, SerialSettings settings) {
        PortName parsed = PortName.parse(portName);
        if (parsed instanceof PortName.Tcp tcp) {
            return new TcpSerialLink(tcp.host(), tcp.port());
        }
        return new JSerialCommLink(((PortName.Device) parsed).path(), settings);
    }

    /**
     * Creates and opens a link for {@code portName}.
     *
     * @throws InvalidPortNameException when the name is malformed
     * @throws IOException naming the port when it cannot be opened
     */
    public static SerialLink open(String portName, SerialSettings settings) throws IOException {
        SerialLink link = create(portName, settings);
        link.open();
        return link;
    }
}
