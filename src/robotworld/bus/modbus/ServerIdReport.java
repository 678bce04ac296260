package robotworld.bus.modbus;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The answer to Report Server ID (function 0x11): {@code 11 count serverId... runIndicator additionalData...}.
 * The Modbus specification leaves the server ID's length to the device, so the run indicator (0xFF = running,
 * which our modules use as the thesis's "OK" status; 0x00 = not running) has no fixed position:
 * <ul>
 * <li>when the last byte is 0x00 or 0xFF it is the run indicator and everything before it the server ID: the
 *     layout of most stacks (an ID of any length, then the indicator, no additional data), and of our modules;</li>
 * <li>otherwise the first 0x00 or 0xFF after the first ID byte is the run indicator and the bytes after it are
 *     additional data: a short ID followed by data such as a version text (libmodbus sends a one-byte ID, 0xFF,
 *     then "LMB" and its version).</li>
 * </ul>
 * A report with no such byte is malformed.
 */
public record ServerIdReport(byte[] serverId, boolean running, byte[] additionalData) {

    /** Run indicator value for "ON". */
    public static final int RUNNING = 0xFF;
    /** Run indicator value for "OFF". */
    public static final int STOPPED = 0x00;

    public ServerIdReport {
        serverId = serverId.clone();
        additionalData = additionalData.clone();
    }

    @Override
    public byte[] serverId() {
        return serverId.clone();
    }

    @Override
    public byte[] additionalData() {
        return additionalData.clone();
    }

    /** The server ID for people: printable ASCII as text, anything else as hex. */
    public String serverIdText() {
        for (byte b : serverId) {
            if (b < 0x20 || b > 0x7E) {
                return RtuFrame.hex(serverId, serverId.length);
            }
        }
        return new String(serverId, StandardCharsets.US_ASCII);
    }

    /**
     * Decodes a response PDU.
     *
     * @throws MalformedPduException when the byte count is wrong or no byte can be the run indicator
     */
    public static ServerIdReport decode(byte[] pdu) {
        if (pdu.length < 3 || (pdu[0] & 0xFF) != FunctionCodes.REPORT_SERVER_ID) {
            throw new MalformedPduException("not a server ID report: " + RtuFrame.hex(pdu, pdu.length));
        }
        int count = pdu[1] & 0xFF;
        if (count != pdu.length - 2) {
            throw new MalformedPduException("server ID report counts " + count + " bytes but carries "
                    + (pdu.length - 2));
        }
        int last = pdu.length - 1;
        if (isIndicator(pdu[last])) {
            return new ServerIdReport(Arrays.copyOfRange(pdu, 2, last), (pdu[last] & 0xFF) == RUNNING, new byte[0]);
        }
        for (int i = 3; i < last; i++) { // at least one ID byte first
            if (isIndicator(pdu[i])) {
                return new ServerIdReport(Arrays.copyOfRange(pdu, 2, i), (pdu[i] & 0xFF) == RUNNING,
                        Arrays.copyOfRange(pdu, i + 1, pdu.length));
            }
        }
        throw new MalformedPduException("no run indicator (0x00 or 0xFF) in server ID report "
                + RtuFrame.hex(pdu, pdu.length));
    }

    private static boolean isIndicator(byte b) {
        return (b & 0xFF) == RUNNING || (b & 0xFF) == STOPPED;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof ServerIdReport that && Arrays.equals(serverId, that.serverId)
                && running == that.running && Arrays.equals(additionalData, that.additionalData);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * Arrays.hashCode(serverId) + Boolean.hashCode(running)) + Arrays.hashCode(additionalData);
    }

    @Override
    public String toString() {
        return "ServerIdReport[id " + serverIdText() + ", " + (running ? "running" : "stopped") + ", "
                + additionalData.length + " data bytes]";
    }
}
