package robotworld.bus.modbus;

import static robotworld.bus.modbus.FunctionCodes.DIAGNOSTICS;
import static robotworld.bus.modbus.FunctionCodes.ENCAPSULATED_INTERFACE;
import static robotworld.bus.modbus.FunctionCodes.EXCEPTION_BIT;
import static robotworld.bus.modbus.FunctionCodes.MEI_READ_DEVICE_ID;
import static robotworld.bus.modbus.FunctionCodes.REPORT_SERVER_ID;

/** Frame lengths of requests (what a server receives) and of responses (what a client receives). */
public final class FrameLengths {

    /** Address, function code and CRC. */
    private static final int OVERHEAD = 4;

    private FrameLengths() {
    }

    /** Lengths of request frames, for the server side. */
    public static FrameLength requests() {
        return FrameLengths::requestLength;
    }

    /** Lengths of the response to a request with this PDU, for the client side. */
    public static FrameLength responseTo(byte[] requestPdu) {
        int requested = requestPdu[0] & 0xFF;
        int requestLength = requestPdu.length + 3;
        return (buffer, have) -> responseLength(requested, requestLength, buffer, have);
    }

    private static int requestLength(byte[] b, int have) {
        if (have < 2) {
            return FrameLength.NEED_MORE;
        }
        int function = b[1] & 0xFF;
        return switch (function) {
            case 0x01, 0x02, 0x03, 0x04, 0x05, 0x06 -> 8;
            case 0x0F, 0x10 -> have < 7 ? FrameLength.NEED_MORE : 9 + (b[6] & 0xFF);
            case DIAGNOSTICS -> diagnosticsRequestLength(b, have);
            case 0x07, 0x0B, 0x0C, REPORT_SERVER_ID -> OVERHEAD;
            case 0x16 -> 10;
            case 0x17 -> have < 11 ? FrameLength.NEED_MORE : 13 + (b[10] & 0xFF);
            case ENCAPSULATED_INTERFACE -> have < 3 ? FrameLength.NEED_MORE
                    : (b[2] & 0xFF) == MEI_READ_DEVICE_ID ? 7 : FrameLength.UNKNOWN;
            default -> FrameLength.UNKNOWN;
        };
    }

    /**
     * Return Query Data (sub-function 0) may carry any number of data words, and nothing in the frame counts them:
     * the frame is the shortest even-sized prefix whose CRC is right (a false match has odds of 1 in 65536 per
     * candidate; a wrong guess fails the request's echo, never a write). Other sub-functions carry one word.
     */
    private static int diagnosticsRequestLength(byte[] b, int have) {
        if (have < 4) {
            return FrameLength.NEED_MORE;
        }
        if (((b[2] & 0xFF) << 8 | b[3] & 0xFF) != FunctionCodes.DIAGNOSTICS_RETURN_QUERY_DATA) {
            return 8;
        }
        for (int length = 6; length <= Math.min(have, RtuFrame.MAX_LENGTH); length += 2) {
            if (Crc16.isValidFrame(b, length)) {
                return length;
            }
        }
        return have >= RtuFrame.MAX_LENGTH ? RtuFrame.MAX_LENGTH + 1 : FrameLength.NEED_MORE;
    }

    private static int responseLength(int requested, int requestLength, byte[] b, int have) {
        if (have < 2) {
            return FrameLength.NEED_MORE;
        }
        int function = b[1] & 0xFF;
        if (function == (requested | EXCEPTION_BIT)) {
            return 5;
        }
        if (function != requested) {
            return FrameLength.UNKNOWN;
        }
        return switch (function) {
            case 0x01, 0x02, 0x03, 0x04, 0x0C, 0x17, REPORT_SERVER_ID ->
                    have < 3 ? FrameLength.NEED_MORE : 5 + (b[2] & 0xFF);
            case 0x05, 0x06, 0x0F, 0x10 -> 8;
            case 0x07 -> 5;
            case 0x0B -> 8;
            case 0x16 -> 10;
            case DIAGNOSTICS -> requestLength; // an echo
            case ENCAPSULATED_INTERFACE -> deviceIdentificationLength(b, have);
            default -> FrameLength.UNKNOWN;
        };
    }

    /**
     * address, 0x2B, 0x0E, read code, conformity, more follows, next object, object count, then per object its
     * id, length and value; then the CRC.
     */
    private static int deviceIdentificationLength(byte[] b, int have) {
        if (have < 3) {
            return FrameLength.NEED_MORE;
        }
        if ((b[2] & 0xFF) != MEI_READ_DEVICE_ID) {
            return FrameLength.UNKNOWN;
        }
        if (have < 8) {
            return FrameLength.NEED_MORE;
        }
        int objects = b[7] & 0xFF;
        int position = 8;
        for (int i = 0; i < objects; i++) {
            if (have < position + 2) {
                return FrameLength.NEED_MORE;
            }
            position += 2 + (b[position + 1] & 0xFF);
            if (position > RtuFrame.MAX_LENGTH) {
                return FrameLength.UNKNOWN; // garbage: let the CRC reject it
            }
        }
        return position + 2;
    }
}
