package robotworld.sim;

import java.io.IOException;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.SerialLink;
import robotworld.bus.TcpSerialLink;
import robotworld.x10.CM11aClock;
import robotworld.x10.CM11aStatus;
import robotworld.x10.DimSteps;
import robotworld.x10.HouseCode;
import robotworld.x10.X10Address;
import robotworld.x10.X10Function;

/**
 * A simulated CM11A computer interface with X10 lamp and appliance modules on its power line. It answers the
 * serial protocol as the real interface does (checksum echo, 0x00 acknowledge, 0x55 after the power-line time,
 * 0x5A polls and uploads, 0xA5 polls after a power failure until the clock comes, the 14-byte status), with real
 * or fast timing, and lets tests inject power-line traffic (remote controls, motion sensors) and checksum faults.
 *
 * <p>Hosts reach it over TCP on 127.0.0.1 ({@link #listen(int)}) or over any open {@link SerialLink}, such as one
 * end of a socat pty pair ({@link #attach(SerialLink)}). One host at a time over TCP: a new connection replaces
 * the previous one, as a program opening a serial port takes it over.
 */
public final class SimulatedCm11a implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(SimulatedCm11a.class);

    private final Cm11aDevice device = new Cm11aDevice();
    private final Cm11aTiming timing;
    private final List<LoopbackServer> servers = new ArrayList<>();
    private final List<Cm11aSession> sessions = new ArrayList<>();
    private Cm11aSession tcpSession;
    private boolean closed;

    /** An interface with no modules yet. */
    public SimulatedCm11a(Cm11aTiming timing) {
        this.timing = timing;
    }

    /** An interface with the modules of {@code deviceSpec}, e.g. {@code A1=lamp,A3=appliance}. */
    public static SimulatedCm11a withDevices(Cm11aTiming timing, String deviceSpec) {
        SimulatedCm11a sim = new SimulatedCm11a(timing);
        DeviceSpec.parse(deviceSpec).forEach(sim::add);
        return sim;
    }

    /** The timing in use. */
    public Cm11aTiming timing() {
        return timing;
    }

    // ----- modules -----

    /** Puts a module on the power line. */
    public <M extends SimulatedX10Module> M add(M module) {
        device.powerLine.add(module);
        return module;
    }

    /** Puts a lamp module at {@code address} on the power line. */
    public SimulatedLampModule addLamp(X10Address address) {
        return add(new SimulatedLampModule(address));
    }

    /** Puts an appliance module at {@code address} on the power line. */
    public SimulatedApplianceModule addAppliance(X10Address address) {
        return add(new SimulatedApplianceModule(address));
    }

    /** All modules, in the order they were added. */
    public List<SimulatedX10Module> modules() {
        return List.copyOf(device.powerLine.modules());
    }

    /** The lamp at {@code address}; fails when there is none. */
    public SimulatedLampModule lamp(X10Address address) {
        if (device.powerLine.module(address) instanceof SimulatedLampModule lamp) {
            return lamp;
        }
        throw new IllegalArgumentException("no simulated lamp at " + address);
    }

    /** The appliance module at {@code address}; fails when there is none. */
    public SimulatedApplianceModule appliance(X10Address address) {
        if (device.powerLine.module(address) instanceof SimulatedApplianceModule appliance) {
            return appliance;
        }
        throw new IllegalArgumentException("no simulated appliance at " + address);
    }

    /** Everything transmitted on the power line so far, e.g. "A3", "A On", "A Dim 11". */
    public List<String> powerLineLog() {
        return device.powerLine.log();
    }

    /**
     * Calls {@code observer} with each transmission on the power line (from the host or injected), e.g. "A On",
     * on the thread that caused it.
     */
    public void onPowerLine(java.util.function.Consumer<String> observer) {
        device.powerLine.observe(observer);
    }

    /** The serial traffic so far. */
    public WireLog wire() {
        return device.wire;
    }

    // ----- connections -----

    /**
     * Listens on 127.0.0.1:{@code port} (0 picks a free port).
     *
     * @return the port name for hosts, e.g. {@code tcp://127.0.0.1:40123}
     */
    public synchronized String listen(int port) throws IOException {
        LoopbackServer server = new LoopbackServer(port, "cm11a-sim", this::serveTcp);
        servers.add(server);
        LOG.debug("simulated CM11A listening on tcp://127.0.0.1:{}", server.port());
        return "tcp://127.0.0.1:" + server.port();
    }

    private synchronized void serveTcp(Socket socket) {
        try {
            if (closed) {
                socket.close();
                return;
            }
            if (tcpSession != null) {
                tcpSession.close(); // the newest host takes the port over
            }
            tcpSession = start(new TcpSerialLink(socket));
        } catch (IOException e) {
            LOG.warn("cannot serve {}: {}", socket, e.getMessage());
        }
    }

    /** Serves the host at the other end of an open link (e.g. a pty) until the link closes. */
    public synchronized void attach(SerialLink link) {
        if (closed) {
            throw new IllegalStateException("the simulator is closed");
        }
        if (!link.isOpen()) {
            throw new IllegalArgumentException(link.portName() + ": the link must be open");
        }
        start(link);
    }

    private Cm11aSession start(SerialLink link) {
        sessions.removeIf(Cm11aSession::hasEnded);
        Cm11aSession session = new Cm11aSession(device, timing, link);
        sessions.add(session);
        Thread thread = new Thread(session, "cm11a-sim " + link.portName());
        thread.setDaemon(true);
        thread.start();
        return session;
    }

    // ----- power failure, clock, status -----

    /** Simulates a power failure: the interface polls 0xA5 each poll interval until the host sends the clock. */
    public void powerFail() {
        device.powerFail();
    }

    /** Unplugs the interface: it stays connected but answers nothing, like a dead device. */
    public void powerOff() {
        device.powerOff();
    }

    /** Plugs the interface in again after {@link #powerOff()}; it polls 0xA5 until the host sends the clock. */
    public void powerOn() {
        device.powerOn();
    }

    /** Whether the interface is still waiting for the clock after a power failure. */
    public boolean isPowerFailed() {
        return device.isPowerFailed();
    }

    /** The last clock the host sent, if any. */
    public Optional<CM11aClock> lastClock() {
        return device.lastClock();
    }

    /** The status the interface would answer to 0x8B now. */
    public CM11aStatus status() {
        return device.status();
    }

    // ----- faults and power-line traffic -----

    /** The next {@code count} checksums the interface sends are wrong. */
    public void injectBadChecksums(int count) {
        device.injectBadChecksums(count);
    }

    /**
     * Another transmitter (a remote control, a motion sensor) sends address + function on the power line: the
     * modules react and the interface polls the host to upload it.
     */
    public void receiveFromPowerLine(X10Address address, X10Function function) {
        if (function.usesDimSteps() || function == X10Function.EXTENDED_CODE) {
            throw new IllegalArgumentException(function + " needs more data: use the dim/bright method");
        }
        device.powerLine.address(address);
        device.powerLine.function(address.house(), function, 0);
        int functionByte = address.house().code() << 4 | function.code();
        device.uploads.add(new byte[] {(byte) address.code(), (byte) functionByte}, new boolean[] {false, true});
    }

    /** Another transmitter sends address + Dim or Bright by {@code steps} of 22; uploaded with a level 0..210. */
    public void receiveFromPowerLine(X10Address address, X10Function dimOrBright, int steps) {
        if (!dimOrBright.usesDimSteps() || steps < 0 || steps > 22) {
            throw new IllegalArgumentException("only Dim or Bright by 0..22 steps, was " + dimOrBright + " " + steps);
        }
        device.powerLine.address(address);
        device.powerLine.function(address.house(), dimOrBright, steps);
        int functionByte = address.house().code() << 4 | dimOrBright.code();
        device.uploads.add(new byte[] {(byte) address.code(), (byte) functionByte,
            (byte) DimSteps.toUploadLevel(steps)}, new boolean[] {false, true, false});
    }

    /** Another transmitter sends a house-wide function (e.g. All Lights Off) on the power line. */
    public void receiveHouseFunction(HouseCode house, X10Function function) {
        if (!function.isHouseWide()) {
            throw new IllegalArgumentException(function + " is not a house-wide function");
        }
        device.powerLine.function(house, function, 0);
        device.uploads.add(new byte[] {(byte) (house.code() << 4 | function.code())}, new boolean[] {true});
    }

    /** A hand-held remote control sends {@code function} (On, Off, ...) to {@code address}. */
    public void remoteControl(X10Address address, X10Function function) {
        receiveFromPowerLine(address, function);
    }

    /** A motion sensor at {@code address} reports motion (it sends On). */
    public void motionDetected(X10Address address) {
        receiveFromPowerLine(address, X10Function.ON);
    }

    /** A motion sensor at {@code address} reports that motion has stopped (it sends Off). */
    public void motionCleared(X10Address address) {
        receiveFromPowerLine(address, X10Function.OFF);
    }

    // ----- lifecycle -----

    /** Stops listening and ends every session. */
    @Override
    public synchronized void close() {
        closed = true;
        servers.forEach(LoopbackServer::close);
        sessions.forEach(Cm11aSession::close);
    }
}
