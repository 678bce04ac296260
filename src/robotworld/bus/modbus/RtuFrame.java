package robotworld.bus.modbus;

import java.util.Arrays;
import java.util.HexFormat;

/**
 * One Modbus RTU frame: the server address and the PDU (function code plus data). On the wire the CRC follows.
 *
 * @param address 0 (broadcast) or 1..247; 248..255 are reserved but still carried, so stray frames can be shown
 * @param pdu function code and data, 1..253 bytes
 */
public record RtuFrame(int address, byte[] pdu) {

    /** The largest RTU frame: address, 253 PDU bytes, CRC. */
    public static final int MAX_LENGTH = 256;

    public RtuFrame {
        if (address < 0 || address > 255) {
            throw new IllegalArgumentException("address " + address + " is outside 0..255");
        }
        if (pdu.length < 1 || pdu.length > MAX_LENGTH - 3) {
            throw new IllegalArgumentException("a PDU has 1..253 bytes, not " + pdu.length);
        }
        pdu = pdu.clone();
    }

    /** The function code (with the exception bit, if set). */
    public int functionCode() {
        return pdu[0] & 0xFF;
    }

    @Override
    public byte[] pdu() {
        return pdu.clone();
    }

    /** The bytes on the wire: address, PDU, CRC low byte, CRC high byte. */
    public byte[] encode() {
        byte[] frame = new byte[pdu.length + 3];
        frame[0] = (byte) address;
        System.arraycopy(pdu, 0, frame, 1, pdu.length);
        int crc = Crc16.of(frame, 0, pdu.length + 1);
        frame[frame.length - 2] = (byte) crc;
        frame[frame.length - 1] = (byte) (crc >>> 8);
        return frame;
    }

    /**
     * Decodes wire bytes whose CRC was already checked ({@link Crc16#isValidFrame}).
     *
     * @throws IllegalArgumentException when the bytes are too short or the CRC is wrong
     */
    public static RtuFrame decode(byte[] bytes, int length) {
        if (!Crc16.isValidFrame(bytes, length)) {
            throw new IllegalArgumentException("not a valid RTU frame: " + hex(bytes, length));
        }
        return new RtuFrame(bytes[0] & 0xFF, Arrays.copyOfRange(bytes, 1, length - 2));
    }

    /** Bytes as spaced hex for messages and logs. */
    public static String hex(byte[] bytes, int length) {
        return HexFormat.ofDelimiter(" ").formatHex(bytes, 0, Math.min(length, bytes.length));
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof RtuFrame that && address == that.address && Arrays.equals(pdu, that.pdu);
    }

    @Override
    public int hashCode() {
        return 31 * address + Arrays.hashCode(pdu);
    }

    @Override
    public String toString() {
        return "RtuFrame[address " + address + ": " + hex(pdu, pdu.length) + "]";
    }
}
