package robotworld.bus;

import java.io.Closeable;
import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import robotworld.bus.modbus.DeviceIdentification;
import robotworld.bus.modbus.MalformedPduException;
import robotworld.bus.modbus.Pdus;
import robotworld.bus.modbus.RtuFrame;
import robotworld.bus.modbus.RtuTiming;
import robotworld.bus.modbus.ServerIdReport;

/**
 * The robot's module bus: Modbus RTU on RS-485, reached through a serial port or a {@code tcp://} bridge. This is
 * the class a robot description names in {@code <TalkToBusClass>}; module proxies ({@link MotorModuleProxy} and
 * its siblings) talk through it.
 *
 * <p>Calls are serialised (one transaction on the line at a time), so proxies on several threads may share a
 * bus. Failures are unchecked {@link BusException}s naming the module, its address and the port.
 */
public final class RS485Bus implements Closeable {

    /** How many transactions a split identification may take (one per object at most, 3 basic objects). */
    private static final int MAX_IDENTIFICATION_PARTS = 8;

    /** The line speed used when none is given. */
    public static final int DEFAULT_BAUD = 115_200;

    private final SerialLink link;
    private final SerialSettings settings;
    private final BusTiming timing;
    private final RtuMaster master;
    private final Map<Integer, String> moduleNames = new ConcurrentHashMap<>();
    private final BusWatchdog watchdog = new BusWatchdog(this);

    /** Opens the bus on {@code portName} ({@code /dev/ttyUSB0}, {@code COM4}, {@code tcp://host:port}) at 115200 8N1. */
    public RS485Bus(String portName) throws IOException {
        this(portName, SerialSettings.eightNoneOne(DEFAULT_BAUD), BusTiming.defaults());
    }

    /** Opens the bus on {@code portName} with the given line settings and timing. */
    public RS485Bus(String portName, SerialSettings settings, BusTiming timing) throws IOException {
        this(SerialLinks.create(portName, settings), settings, timing);
    }

    /** Runs the bus over a link (opened here if it is not open yet). */
    public RS485Bus(SerialLink link, SerialSettings settings, BusTiming timing) throws IOException {
        this.link = Objects.requireNonNull(link, "link");
        this.settings = Objects.requireNonNull(settings, "settings");
        this.timing = Objects.requireNonNull(timing, "timing");
        link.open();
        this.master = new RtuMaster(link, RtuTiming.of(settings.baudRate(), settings.characterTimeNanos()), timing,
                this::describe);
    }

    public String portName() {
        return link.portName();
    }

    public SerialSettings settings() {
        return settings;
    }

    public BusTiming timing() {
        return timing;
    }

    /**
     * Gives an address a name for error messages; proxies do this, so a failure reads
     * "BumperModule 'Bumper-Sensor' at address 2 on tcp://...: no reply ...".
     */
    public void nameModule(int address, String name) {
        moduleNames.put(checkAddress(address), Objects.requireNonNull(name, "name"));
    }

    /** How an address is named in messages. */
    public String describe(int address) {
        String name = moduleNames.get(address);
        return name == null ? "address " + address : name + " at address " + address;
    }

    /**
     * How the echo of an RS-485 adapter without echo suppression is handled: {@link EchoCancellation#AUTO} (the
     * default) detects it and drops it from then on, {@code ON} always drops it, {@code OFF} fails calls with
     * {@link AdapterEchoException} saying so.
     */
    public RS485Bus echoCancellation(EchoCancellation mode) {
        master.echoCancellation(Objects.requireNonNull(mode, "mode"));
        return this;
    }

    /** Whether the adapter was seen echoing requests (then, in AUTO mode, their echo is dropped). */
    public boolean echoDetected() {
        return master.echoDetected();
    }

    // ----- the mandatory commands of every module -----

    /**
     * Identification: Read Device Identification (0x2B/0x0E), basic objects; a device that splits them over
     * several transactions ("more follows") is asked until it has sent them all.
     */
    public DeviceIdentification identify(int address) {
        return followIdentification(address, call(address, Pdus.readDeviceIdentification()));
    }

    /** Status: Report Server ID (0x11); a module that is OK reports run indicator 0xFF. */
    public ServerIdReport reportServerId(int address) {
        return decode(address, "status", () -> ServerIdReport.decode(call(address, Pdus.reportServerId())));
    }

    /**
     * Echo: Diagnostics 0x08 sub-function 0x0000; the module must return the {@code words} (one or more)
     * unaltered.
     *
     * @throws BusProtocolException when the echo comes back altered
     */
    public void echo(int address, int... words) {
        byte[] request = Pdus.echo(words);
        byte[] response = call(address, request);
        decode(address, "echo", () -> {
            Pdus.checkEcho(request, response);
            return null;
        });
    }

    // ----- data -----

    /** Reads {@code count} discrete inputs from {@code first} (0-based). */
    public boolean[] readDiscreteInputs(int address, int first, int count) {
        byte[] response = call(address, Pdus.readDiscreteInputs(first, count));
        return decode(address, "discrete inputs", () -> Pdus.decodeBits(response, count));
    }

    /** Reads {@code count} input registers from {@code first} (0-based), as unsigned words. */
    public int[] readInputRegisters(int address, int first, int count) {
        byte[] response = call(address, Pdus.readInputRegisters(first, count));
        return decode(address, "input registers", () -> Pdus.decodeRegisters(response, count));
    }

    /** Reads {@code count} holding registers from {@code first} (0-based), as unsigned words. */
    public int[] readHoldingRegisters(int address, int first, int count) {
        byte[] response = call(address, Pdus.readHoldingRegisters(first, count));
        return decode(address, "holding registers", () -> Pdus.decodeRegisters(response, count));
    }

    /** Writes one holding register ({@code value} as an unsigned word) and waits for the confirmation. */
    public void writeRegister(int address, int register, int value) {
        byte[] request = Pdus.writeSingleRegister(register, value);
        byte[] response = call(address, request);
        decode(address, "write confirmation", () -> {
            Pdus.checkWriteEcho(request, response);
            return null;
        });
    }

    /**
     * Writes one holding register and returns without waiting; the confirmation is read before the next call
     * on this bus and a missing one is logged, not thrown.
     */
    public void writeRegisterQuietly(int address, int register, int value) {
        master.callQuietly(checkAddress(address), Pdus.writeSingleRegister(register, value),
                timing.responseTimeout());
        watchdog.exchanged(address);
    }

    /** Writes consecutive holding registers and waits for the confirmation. */
    public void writeRegisters(int address, int first, int[] values) {
        byte[] request = Pdus.writeMultipleRegisters(first, values);
        byte[] response = call(address, request);
        decode(address, "write confirmation", () -> {
            Pdus.checkWriteEcho(request, response);
            return null;
        });
    }

    // ----- exploration support -----

    /**
     * Asks an address for its identification with the short scan timeout ({@link #scanReplyTimeout()}) and no
     * retry when it stays silent: silence in a scan means "nobody there".
     *
     * @throws BusTimeoutException when nobody answers
     */
    public DeviceIdentification probe(int address) {
        byte[] request = Pdus.readDeviceIdentification();
        byte[] response = master.call(checkAddress(address), request,
                new RtuMaster.CallPolicy(scanReplyTimeout(), timing.attempts(), false));
        return followIdentification(address, response); // the module answered: further parts at normal timing
    }

    /** Asks for the rest of a split identification, each part from where the previous one said to go on. */
    private DeviceIdentification followIdentification(int address, byte[] firstResponse) {
        List<DeviceIdentification.Part> parts = new ArrayList<>();
        DeviceIdentification.Part part = decode(address, "identification",
                () -> DeviceIdentification.decodePart(firstResponse));
        parts.add(part);
        int startedAt = 0;
        while (part.moreFollows()) {
            int next = part.nextObjectId();
            if (next <= startedAt || parts.size() >= MAX_IDENTIFICATION_PARTS) {
                throw new BusProtocolException(link.portName(), address, describe(address) + " on "
                        + link.portName() + ": malformed identification: 'more follows' does not progress (next "
                        + "object " + next + " after a part that started at " + startedAt + ")");
            }
            startedAt = next;
            byte[] response = call(address, Pdus.readDeviceIdentification(next));
            part = decode(address, "identification", () -> DeviceIdentification.decodePart(response));
            parts.add(part);
        }
        return DeviceIdentification.of(parts);
    }

    /**
     * How long a probe waits for the start of a reply after its request has left the wire: the 3.5-character
     * silence a module waits before answering, one character, plus the scan allowance.
     */
    public Duration scanReplyTimeout() {
        RtuTiming rtu = master.timing();
        return Duration.ofNanos(rtu.t35Nanos() + rtu.characterNanos()).plus(timing.scanAllowance());
    }

    /**
     * Who hears of valid frames that answer no current request (late replies, from whichever address): bus
     * exploration asks those addresses again, so a module slower than the scan timeout is not lost.
     */
    public void onStrayFrame(Consumer<RtuFrame> listener) {
        master.onStrayFrame(listener);
    }

    /**
     * Who hears of addresses whose exchange was disturbed (a corrupted or cut-short reply while asking them, or
     * bytes starting with their address that were no whole frame): bus exploration asks them again. The second
     * argument tells whether the bytes started like a reply from that address (address, then the function asked):
     * then a module is there.
     */
    public void onDisturbance(java.util.function.ObjIntConsumer<Boolean> listener) {
        master.onDisturbance(listener == null ? null : (address, heard) -> listener.accept(heard, address));
    }

    /**
     * Identification asked once more with the normal reply timeout, retried on corrupted replies but not on
     * silence: how exploration asks again at an address whose exchange was disturbed.
     *
     * @throws BusTimeoutException when nobody answers
     */
    public DeviceIdentification reprobe(int address) {
        byte[] response = master.call(checkAddress(address), Pdus.readDeviceIdentification(),
                new RtuMaster.CallPolicy(timing.responseTimeout(), timing.attempts(), false));
        return followIdentification(address, response);
    }

    /** How fast reply bytes arrive on this line (see {@link ReplyPacing}). */
    public ReplyPacing replyPacing() {
        return master.pacing();
    }

    /**
     * Listens for late replies, reporting them to the stray-frame listener: at least {@code window}, and on until
     * the late-reply window (four reply timeouts) of every unanswered request has closed, or all those replies
     * have come.
     */
    public void listenForStrays(Duration window) {
        master.listenForStrays(window, Pdus.readDeviceIdentification());
    }

    // ----- safety -----

    /**
     * Arms the communication watchdog of the module at {@code address} and keeps it fed while this bus is open
     * ({@link BusWatchdog}).
     *
     * @return false when the module has no watchdog (logged)
     */
    public boolean armWatchdog(int address, Duration timeout, Consumer<String> onTrip) {
        return watchdog.arm(checkAddress(address), timeout, onTrip);
    }

    /**
     * {@link #armWatchdog(int, Duration, Consumer)}, and tells {@code onFoundTripped} when the module is found to
     * have stopped by its watchdog before this program armed it ({@link BusWatchdog#arm(int, Duration, Consumer,
     * Consumer)}).
     */
    public boolean armWatchdog(int address, Duration timeout, Consumer<String> onTrip,
                               Consumer<String> onFoundTripped) {
        return watchdog.arm(checkAddress(address), timeout, onTrip, onFoundTripped);
    }

    /** The watchdogs this bus keeps fed. */
    public BusWatchdog watchdog() {
        return watchdog;
    }

    /** Counters since the bus was opened. */
    public BusStatistics statistics() {
        return master.statistics();
    }

    /** Stops feeding the modules' watchdogs (they stay armed) and closes the link. */
    @Override
    public void close() throws IOException {
        watchdog.close();
        link.close();
    }

    @Override
    public String toString() {
        return "RS485Bus " + link.portName() + " (" + settings + ")";
    }

    private byte[] call(int address, byte[] pdu) {
        try {
            byte[] reply = master.call(checkAddress(address), pdu,
                    new RtuMaster.CallPolicy(timing.responseTimeout(), timing.attempts(), true));
            watchdog.exchanged(address);
            return reply;
        } catch (ModuleRefusedException refused) {
            watchdog.exchanged(address); // a refusal is an answer: the module heard the request
            throw refused;
        }
    }

    private interface Decoder<T> {
        T decode();
    }

    private <T> T decode(int address, String what, Decoder<T> decoder) {
        try {
            return decoder.decode();
        } catch (MalformedPduException e) {
            throw new BusProtocolException(link.portName(), address, describe(address) + " on " + link.portName()
                    + ": malformed " + what + ": " + e.getMessage());
        }
    }

    private static int checkAddress(int address) {
        if (address < 1 || address > 247) {
            throw new IllegalArgumentException("bus address " + address + " is outside 1..247");
        }
        return address;
    }
}
