package robotworld.explorer.frames;

import com.fazecast.jSerialComm.SerialPort;
import java.util.ArrayList;
import java.util.List;

/** The ports offered in the explore frame: every serial port jSerialComm finds, then a {@code tcp://} example. */
final class SerialPortChoices {

    /** A robot simulator's default address (docs: {@code rwe simulate robot}). */
    static final String TCP_EXAMPLE = "tcp://127.0.0.1:5020";

    private SerialPortChoices() {
    }

    static List<String> detected() {
        List<String> ports = new ArrayList<>();
        try {
            for (SerialPort port : SerialPort.getCommPorts()) {
                ports.add(port.getSystemPortPath());
            }
        } catch (RuntimeException | LinkageError e) {
            // no native support on this platform: the field stays editable for device paths and tcp://
        }
        ports.add(TCP_EXAMPLE);
        return ports;
    }
}
