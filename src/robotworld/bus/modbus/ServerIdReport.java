package robotworld.bus.modbus;

import java.util.Arrays;

/**
 * The answer to Report Server ID (function 0x11): a server ID, the run indicator (0xFF = running, which our
 * modules use as the thesis's "OK" status) and device-specific data.
 */
public record ServerIdReport(int serverId, boolean running, byte[] additionalData) {

    /** Run indicator value for "ON". */
    public static final int RUNNING = 0xFF;

    public ServerIdReport {
        additionalData = additionalData.clone();
    }

    @Override
    public byte[] additionalData() {
        return additionalData.clone();
    }

    /**
     * Decodes {@code 11 count serverId runIndicator data...}. Run indicators other than 0x00 and 0xFF are
     * refused: they mean the module is confused, not that it is stopped.
     *
     * @throws MalformedPduException when the layout is broken
     */
    public static ServerIdReport decode(byte[] pdu) {
        if (pdu.length < 4 || (pdu[0] & 0xFF) != FunctionCodes.REPORT_SERVER_ID) {
            throw new MalformedPduException("not a server ID report: " + RtuFrame.hex(pdu, pdu.length));
        }
        int count = pdu[1] & 0xFF;
        if (count != pdu.length - 2) {
            throw new MalformedPduException("server ID report counts " + count + " bytes but carries "
                    + (pdu.length - 2));
        }
        int indicator = pdu[3] & 0xFF;
        if (indicator != RUNNING && indicator != 0) {
            throw new MalformedPduException(String.format("run indicator 0x%02X is neither 0x00 nor 0xFF", indicator));
        }
        return new ServerIdReport(pdu[2] & 0xFF, indicator == RUNNING, Arrays.copyOfRange(pdu, 4, pdu.length));
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof ServerIdReport that && serverId == that.serverId && running == that.running
                && Arrays.equals(additionalData, that.additionalData);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * serverId + Boolean.hashCode(running)) + Arrays.hashCode(additionalData);
    }

    @Override
    public String toString() {
        return "ServerIdReport[id " + serverId + ", " + (running ? "running" : "stopped") + ", "
                + additionalData.length + " data bytes]";
    }
}
