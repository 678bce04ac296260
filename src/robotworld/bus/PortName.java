package robotworld.bus;

import java.util.Locale;

/**
 * A parsed port name: either a serial device ({@code /dev/ttyUSB0}, {@code COM4}, a pty link) or a raw
 * serial-over-TCP endpoint ({@code tcp://host:port}, as served by ser2net or the simulators).
 */
public sealed interface PortName permits PortName.Device, PortName.Tcp {

    /** The scheme prefix that marks a TCP endpoint. */
    String TCP_PREFIX = "tcp://";

    /** The name as the user wrote it (trimmed). */
    String text();

    /** A serial device opened through the operating system, e.g. {@code /dev/ttyUSB0} or {@code COM4}. */
    record Device(String path) implements PortName {
        @Override
        public String text() {
            return path;
        }
    }

    /** A raw byte stream over TCP to {@code host:port}. */
    record Tcp(String host, int port) implements PortName {
        @Override
        public String text() {
            return TCP_PREFIX + (host.contains(":") ? "[" + host + "]" : host) + ":" + port;
        }
    }

    /**
     * Parses a port name.
     *
     * @throws InvalidPortNameException with a message that says what is wrong and what would be right
     */
    static PortName parse(String name) {
        return parse(name, 1);
    }

    /**
     * Parses a port name for a server that listens on it: as {@link #parse}, but {@code tcp://host:0} is allowed
     * and means "any free port".
     *
     * @throws InvalidPortNameException with a message that says what is wrong and what would be right
     */
    static PortName parseListening(String name) {
        return parse(name, 0);
    }

    private static PortName parse(String name, int lowestPort) {
        if (name == null || name.isBlank()) {
            throw new InvalidPortNameException("the port name is empty: give a serial device (e.g. /dev/ttyUSB0, "
                    + "COM4) or tcp://HOST:PORT");
        }
        String trimmed = name.trim();
        int schemeEnd = trimmed.indexOf("://");
        if (schemeEnd < 0) {
            return new Device(trimmed);
        }
        String scheme = trimmed.substring(0, schemeEnd).toLowerCase(Locale.ROOT);
        if (!scheme.equals("tcp")) {
            throw new InvalidPortNameException("unsupported port scheme '" + scheme + "' in '" + trimmed
                    + "': use a serial device (e.g. /dev/ttyUSB0, COM4) or tcp://HOST:PORT");
        }
        return parseTcp(trimmed, trimmed.substring(schemeEnd + 3), lowestPort);
    }

    private static Tcp parseTcp(String whole, String rest, int lowestPort) {
        String host;
        String portText;
        if (rest.startsWith("[")) {
            int close = rest.indexOf(']');
            if (close < 0 || close + 1 >= rest.length() || rest.charAt(close + 1) != ':') {
                throw new InvalidPortNameException("'" + whole + "' is not tcp://[IPv6]:PORT");
            }
            host = rest.substring(1, close);
            portText = rest.substring(close + 2);
        } else {
            int colon = rest.lastIndexOf(':');
            if (colon < 0) {
                throw new InvalidPortNameException("'" + whole + "' has no port: write tcp://HOST:PORT");
            }
            host = rest.substring(0, colon);
            portText = rest.substring(colon + 1);
            if (host.contains(":")) {
                throw new InvalidPortNameException("'" + whole + "': put an IPv6 host in brackets, "
                        + "tcp://[::1]:PORT");
            }
        }
        if (host.isEmpty() || host.contains("/")) {
            throw new InvalidPortNameException("'" + whole + "' has no valid host: write tcp://HOST:PORT");
        }
        int port;
        try {
            port = Integer.parseInt(portText);
        } catch (NumberFormatException e) {
            throw new InvalidPortNameException("'" + whole + "': port '" + portText + "' is not a number");
        }
        if (port < lowestPort || port > 65535) {
            throw new InvalidPortNameException("'" + whole + "': port " + port + " is outside " + lowestPort
                    + "..65535");
        }
        return new Tcp(host, port);
    }
}
