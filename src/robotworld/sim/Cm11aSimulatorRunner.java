package robotworld.sim;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.Locale;
import java.util.stream.Collectors;
import robotworld.bus.JSerialCommLink;
import robotworld.bus.PortName;
import robotworld.bus.SerialLink;
import robotworld.x10.X10Constants;

/**
 * Starts a simulated CM11A for the command line ({@code rwe simulate cm11a}): on {@code tcp://127.0.0.1:PORT}
 * (loopback only) or attached to a serial device such as one end of a socat pty pair.
 */
public final class Cm11aSimulatorRunner {

    private Cm11aSimulatorRunner() {
    }

    /**
     * Builds and starts the simulator.
     *
     * @param port {@code tcp://127.0.0.1:PORT} (or {@code tcp://localhost:PORT}; port 0 picks a free one) or a
     *        serial device path
     * @param devices e.g. {@code A1=lamp,A3=appliance}
     * @param timing real or fast
     * @param startInPowerFail whether the interface first asks for the clock
     * @return the running simulator; close it to stop
     * @throws IllegalArgumentException for a malformed port name, a non-loopback host or a bad device list
     * @throws IOException when the port cannot be bound or opened
     */
    public static Started start(String port, String devices, Cm11aTiming timing, boolean startInPowerFail)
            throws IOException {
        PortName parsed = PortName.parseListening(port);
        SimulatedCm11a sim = SimulatedCm11a.withDevices(timing, devices);
        if (startInPowerFail) {
            sim.powerFail();
        }
        try {
            if (parsed instanceof PortName.Tcp tcp) {
                requireLoopback(tcp);
                return new Started(sim, sim.listen(tcp.port()));
            }
            SerialLink link = new JSerialCommLink(parsed.text(), X10Constants.CM11A_SERIAL);
            link.open();
            sim.attach(link);
            return new Started(sim, parsed.text());
        } catch (IOException | RuntimeException e) {
            sim.close();
            throw e;
        }
    }

    private static void requireLoopback(PortName.Tcp tcp) {
        boolean loopback;
        try {
            loopback = InetAddress.getByName(tcp.host()).isLoopbackAddress();
        } catch (UnknownHostException e) {
            loopback = false;
        }
        if (!loopback) {
            throw new IllegalArgumentException("the simulator listens on 127.0.0.1 only; use tcp://127.0.0.1:"
                    + tcp.port());
        }
    }

    /**
     * A running simulator and the port hosts should use.
     *
     * @param sim the simulator
     * @param portName e.g. {@code tcp://127.0.0.1:40123}
     */
    public record Started(SimulatedCm11a sim, String portName) {

        /** One line for the user, e.g. "simulated CM11A on tcp://127.0.0.1:5000 (real timing): A1 lamp, A3 ...". */
        public String describe() {
            String modules = sim.modules().stream()
                    .map(module -> module.address() + " " + module.kind().name().toLowerCase(Locale.ROOT))
                    .collect(Collectors.joining(", "));
            return "simulated CM11A on " + portName + " (" + (sim.timing().isPaced() ? "real" : "fast")
                    + " timing): " + (modules.isEmpty() ? "no modules" : modules);
        }
    }
}
