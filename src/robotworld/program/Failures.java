package robotworld.program;

import java.net.BindException;
import java.net.ConnectException;
import java.net.NoRouteToHostException;
import java.net.SocketTimeoutException;
import java.net.URI;
import java.net.UnknownHostException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import robotworld.bus.BusException;
import robotworld.bus.BusTimeoutException;
import robotworld.bus.InvalidPortNameException;
import robotworld.bus.PortInUseException;
import robotworld.space.SpaceRequestRejectedException;
import robotworld.space.SpaceUnavailableException;
import robotworld.x10.X10Exception;
import robotworld.x10.X10TimeoutException;
import robotworld.xvsm.ModuleCallException;
import robotworld.xvsm.ModuleCallTimeoutException;

/**
 * Turns a failure into at most three lines a user can act on: what happened, in words, and the fix (the
 * property, option or command to use). Never a stack trace: {@link ParticipantMain} adds that only with
 * {@code -Drwe.debug=true}. Every message this class writes is listed, with its fix, in
 * {@code docs/troubleshooting.md}.
 */
public final class Failures {

    /** At most this many lines describe one failure. */
    public static final int MAX_LINES = 3;

    private static final int MAX_LINE = 300;
    private static final Pattern SERIAL_ERROR = Pattern.compile("cannot open serial port \\(error (\\d+)");
    private static final String DEBUG_HINT = "Run again with -Drwe.debug=true to see where it happened.";

    /** How the fix for a port or a space is written where the failure happened: a property, or an option. */
    public record Fixes(Function<PortFailure, String> choosePort, String chooseSpace) {

        /** In a generated program: the {@code rwe.port.*} property that chose the port, {@code rwe.space.url}. */
        public static Fixes program() {
            return new Fixes(port -> {
                String property = port.property() != null ? port.property() : ParticipantMain.propertyOf(port.port());
                return property == null ? null : "-D" + property + "=PORT";
            }, "-Drwe.space.url=http://HOST:PORT/space");
        }

        /** In an {@code rwe} verb: its options. */
        public static Fixes command(String portOption, String spaceOption) {
            return new Fixes(port -> portOption == null ? null : portOption + " PORT", spaceOption);
        }
    }

    /** The port a failure was about, and (when known) the property that chose it. */
    public record PortFailure(String kind, String port, String property) {
    }

    private Failures() {
    }

    /** The lines for a failure in a generated program of {@code participant} (null when not known). */
    public static List<String> describe(Throwable failure, String participant) {
        return describe(failure, participant, Fixes.program());
    }

    /** The lines for a failure, with the fixes written as {@code fixes} says. */
    public static List<String> describe(Throwable failure, String participant, Fixes fixes) {
        List<String> lines = explain(failure, participant == null ? "" : participant + ": ", fixes);
        List<String> bounded = new ArrayList<>(MAX_LINES);
        for (String line : lines) {
            if (line != null && !line.isBlank() && bounded.size() < MAX_LINES) {
                bounded.add(line.length() > MAX_LINE ? line.substring(0, MAX_LINE - 3) + "..." : line);
            }
        }
        return bounded;
    }

    private static List<String> explain(Throwable failure, String who, Fixes fixes) {
        PortException port = find(failure, PortException.class);
        if (port != null) {
            return portFailure(port, who, fixes);
        }
        SpaceRequestRejectedException rejected = find(failure, SpaceRequestRejectedException.class);
        if (rejected != null) {
            return rejected(rejected, who);
        }
        SpaceUnavailableException unreachable = find(failure, SpaceUnavailableException.class);
        if (unreachable != null) {
            return unreachable(unreachable, who, fixes);
        }
        ModuleCallException call = find(failure, ModuleCallException.class);
        if (call != null) {
            return moduleCall(call, who);
        }
        BusException bus = find(failure, BusException.class);
        if (bus != null) {
            return bus(bus, who, fixes);
        }
        X10Exception x10 = find(failure, X10Exception.class);
        if (x10 != null) {
            return x10(x10, who, fixes);
        }
        BindException bind = find(failure, BindException.class);
        if (bind != null) {
            String choose = choosePort(fixes, new PortFailure("tcp", null, null));
            return List.of(who + "the network port is already in use (" + firstLine(bind.getMessage()) + ").",
                    "Stop the program that uses it, or choose another port" + with(choose) + ".");
        }
        NoSuchFileException missing = find(failure, NoSuchFileException.class);
        if (missing != null) {
            return List.of(who + missing.getFile() + ": no such file");
        }
        AccessDeniedException denied = find(failure, AccessDeniedException.class);
        if (denied != null) {
            return List.of(who + denied.getFile() + ": not allowed to read or write it (check its permissions)");
        }
        if (failure instanceof InterruptedException) {
            return List.of(who + "interrupted; stopped.");
        }
        if (failure instanceof IllegalStateException || failure instanceof IllegalArgumentException) {
            // our own checks: their messages already say what to set ("no bus port for X: set ... -Drwe.port...")
            return List.of(who + firstLine(failure.getMessage()));
        }
        return List.of(who + inWords(failure), DEBUG_HINT);
    }

    // ----- ports -----

    private static List<String> portFailure(PortException failure, String who, Fixes fixes) {
        Throwable cause = failure.getCause();
        String port = failure.port();
        String device = failure.kind().equals("x10") ? "the CM11A" : "the robot's bus adapter";
        String choose = choosePort(fixes, new PortFailure(failure.kind(), port, failure.property()));
        // the simulator to start is the one on the port that was asked for, if that is a TCP port
        String simulatorPort = port != null && port.startsWith("tcp://") ? port
                : failure.kind().equals("x10") ? "tcp://127.0.0.1:5030" : "tcp://127.0.0.1:5020";
        String simulator = failure.kind().equals("x10") ? "rwe simulate cm11a --port " + simulatorPort
                : "rwe simulate robot --config FILE --port " + simulatorPort;
        String message = cause == null ? "" : String.valueOf(cause.getMessage());
        if (cause instanceof InvalidPortNameException) {
            return List.of(who + "'" + port + "' is not a port: " + firstLine(message),
                    "Give a serial device (/dev/ttyUSB0, COM4) or tcp://HOST:PORT" + with(choose) + ".");
        }
        if (find(cause, ConnectException.class) != null) {
            return List.of(who + "nothing answers at " + port + " (connection refused).",
                    "Start the simulator or serial bridge there (" + simulator + ")" + orChoose(choose) + ".");
        }
        if (find(cause, SocketTimeoutException.class) != null || find(cause, NoRouteToHostException.class) != null) {
            return List.of(who + "no connection to " + port + " (" + firstLine(message) + ").",
                    "Check the host name and that the bridge or simulator there runs and is reachable"
                            + orChoose(choose) + ".");
        }
        if (find(cause, UnknownHostException.class) != null) {
            return List.of(who + "unknown host in " + port + ".", "Check the host name" + orChoose(choose) + ".");
        }
        PortInUseException inUse = find(cause, PortInUseException.class);
        if (inUse != null) {
            // the link names the program that holds the port
            String held = firstLine(inUse.getMessage()).replaceAll(":? ?stop that program.*$", "");
            return List.of(who + held + ".", "Stop that program (another copy of this one?)" + orChoose(choose) + ".");
        }
        if (message.contains("not a serial device")) {
            return List.of(who + firstLine(message).replaceAll(": give the device itself.*$", "") + ".",
                    "Give the serial device itself (/dev/ttyUSB0, /dev/serial/by-id/...)" + orChoose(choose) + ".");
        }
        if (find(cause, NoSuchFileException.class) != null || message.contains("no such serial")
                || message.contains("permission denied") || message.contains("busy")
                || message.contains("cannot open serial port")) {
            return serialPort(who, port, message, device, choose);
        }
        return List.of(who + "cannot open " + port + ": " + firstLine(message),
                "Check " + device + " and its cable" + orChoose(choose) + ".");
    }

    /**
     * A serial device that did not open. What the device file says is surer than jSerialComm's error number: no
     * file, a file we may not use, or one that is there and ours to use, so held by another program.
     */
    private static List<String> serialPort(String who, String port, String message, String device, String choose) {
        Path file = devicePath(port);
        Matcher serial = SERIAL_ERROR.matcher(message);
        int errno = serial.find() ? Integer.parseInt(serial.group(1)) : -1;
        boolean missing = file != null ? !Files.exists(file) : message.contains("no such serial") || errno == 2;
        boolean forbidden = message.contains("permission denied") || (file != null ? !missing
                && (!Files.isReadable(file) || !Files.isWritable(file)) : errno == 13 || errno == 1);
        if (missing) {
            return List.of(who + "there is no serial port " + port + " on this computer.",
                    "Plug in " + device + " and check its name (ls /dev/serial/by-id/)" + orChoose(choose)
                            + " (tcp://HOST:PORT for a simulator or serial bridge).");
        }
        if (forbidden) {
            return List.of(who + "not allowed to open " + port + ".",
                    "Add yourself to the group that owns it and log in again: sudo usermod -aG dialout $USER"
                            + " (see docs/hardware.md).");
        }
        return List.of(who + port + " is in use by another program.",
                "Stop that program (another copy of this one? a terminal program, ModemManager?)" + orChoose(choose)
                        + ".");
    }

    /** The device file of a serial port name on this computer, or null where names are not files (COM4). */
    private static Path devicePath(String port) {
        if (port == null || port.contains("://") || System.getProperty("os.name", "").startsWith("Windows")) {
            return null;
        }
        try {
            return port.startsWith("/") ? Path.of(port) : Path.of("/dev", port);
        } catch (java.nio.file.InvalidPathException e) {
            return null;
        }
    }

    private static String choosePort(Fixes fixes, PortFailure failure) {
        return fixes.choosePort().apply(failure);
    }

    private static String with(String choose) {
        return choose == null ? "" : " with " + choose;
    }

    private static String orChoose(String choose) {
        return choose == null ? "" : ", or choose the port with " + choose;
    }

    // ----- the space -----

    private static List<String> unreachable(SpaceUnavailableException failure, String who, Fixes fixes) {
        URI address = failure.address();
        String host = address == null || address.getHost() == null ? "HOST" : address.getHost();
        int port = address == null || address.getPort() < 0 ? 9876 : address.getPort();
        boolean local = host.equals("localhost") || host.startsWith("127.") || host.equals("[::1]");
        String start = local ? "start it with: rwe space --port " + port
                : "start it on " + host + ": rwe space --port " + port + " --bind 0.0.0.0 --token-file FILE";
        return List.of(who + "cannot reach the space at " + (address == null ? "its address" : address) + ".",
                capitalised(start) + (fixes.chooseSpace() == null ? "" : ", or give its address with "
                        + fixes.chooseSpace()) + ".");
    }

    private static List<String> rejected(SpaceRequestRejectedException failure, String who) {
        if (failure.status() == 401 || failure.status() == 403) {
            String fix = "Give the token the server was started with (its --token-file): -Drwe.space.tokenFile=FILE"
                    + " or RWE_SPACE_TOKEN_FILE=FILE.";
            return List.of(who + (tokenGiven() ? "the space server refused the access token."
                    : "the space server needs an access token, and none was given."), fix);
        }
        return List.of(who + "the space server refused a request: " + firstLine(failure.getMessage()),
                "Check that this program and the space server are the same RobotWorldExplorer version. "
                        + DEBUG_HINT);
    }

    private static boolean tokenGiven() {
        for (String property : List.of("rwe.space.token", "rwe.space.tokenFile")) {
            if (System.getProperty(property) != null) {
                return true;
            }
        }
        return System.getenv("RWE_SPACE_TOKEN") != null || System.getenv("RWE_SPACE_TOKEN_FILE") != null;
    }

    // ----- modules -----

    private static List<String> moduleCall(ModuleCallException failure, String who) {
        if (failure instanceof ModuleCallTimeoutException timeout && !timeout.hardwareTimedOut()) {
            return List.of(who + "no answer from " + failure.participant() + "'s " + failure.module() + " within "
                            + timeout.timeoutMillis() + " ms: the program serving it is not running.",
                    "Start " + failure.participant() + "'s program on its computer (in its project: ant run), or"
                            + " allow more time with -Drwe.call.timeout.ms=MS.");
        }
        if (failure instanceof ModuleCallTimeoutException) {
            return List.of(who + firstLine(failure.getMessage()),
                    failure.participant() + "'s computer cannot reach that module: check its power and cable there"
                            + " (or the simulator it uses).");
        }
        return List.of(who + firstLine(failure.getMessage()),
                "Reported by " + failure.participant() + "'s program; its output says more.");
    }

    private static List<String> bus(BusException failure, String who, Fixes fixes) {
        String choose = choosePort(fixes, new PortFailure("bus", failure.port(), null));
        if (failure instanceof BusTimeoutException) {
            return List.of(who + firstLine(failure.getMessage()),
                    "Check that the robot is switched on and its bus connected to " + failure.port()
                            + " (for a simulator: that rwe simulate robot runs there)" + orChoose(choose) + ".");
        }
        return List.of(who + firstLine(failure.getMessage()),
                "Check the connection to " + failure.port() + " (cable, adapter, bridge or simulator)"
                        + orChoose(choose) + ".");
    }

    private static List<String> x10(X10Exception failure, String who, Fixes fixes) {
        String choose = choosePort(fixes, new PortFailure("x10", failure.portName(), null));
        if (failure instanceof X10TimeoutException) {
            return List.of(who + firstLine(failure.getMessage()),
                    "Check that the CM11A on " + failure.portName() + " is plugged in and its serial cable connected"
                            + " (for a simulator: that rwe simulate cm11a runs there)" + orChoose(choose) + ".");
        }
        return List.of(who + firstLine(failure.getMessage()),
                "Check the CM11A's cable and power" + orChoose(choose) + ".");
    }

    // ----- helpers -----

    /** The failure or the first of its causes of the given type. */
    static <T extends Throwable> T find(Throwable failure, Class<T> type) {
        Throwable current = failure;
        for (int depth = 0; current != null && depth < 16; depth++, current = current.getCause()) {
            if (type.isInstance(current)) {
                return type.cast(current);
            }
        }
        return null;
    }

    /** "NullPointerException: x" as "null pointer: x", for failures nothing above explains. */
    private static String inWords(Throwable failure) {
        String kind = failure.getClass().getSimpleName().replaceAll("(Exception|Error)$", "")
                .replaceAll("([a-z])([A-Z])", "$1 $2").toLowerCase(Locale.ROOT);
        String message = failure.getMessage();
        return message == null || message.isBlank() ? "failed (" + kind + ")" : firstLine(message) + " (" + kind + ")";
    }

    private static String firstLine(String message) {
        if (message == null) {
            return "";
        }
        String line = message.strip();
        int end = line.indexOf('\n');
        return end < 0 ? line : line.substring(0, end).strip();
    }

    private static String capitalised(String text) {
        return text.isEmpty() ? text : Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }
}
