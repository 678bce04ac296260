package robotworld.bus.modbus;

/**
 * The CRC-16 of Modbus RTU (polynomial 0xA001 reflected, initial value 0xFFFF). It travels low byte first, which
 * is why a frame with its CRC appended yields a CRC of zero.
 */
public final class Crc16 {

    private static final int[] TABLE = new int[256];

    static {
        for (int i = 0; i < 256; i++) {
            int crc = i;
            for (int bit = 0; bit < 8; bit++) {
                crc = (crc & 1) != 0 ? (crc >>> 1) ^ 0xA001 : crc >>> 1;
            }
            TABLE[i] = crc;
        }
    }

    private Crc16() {
    }

    /** The CRC of {@code length} bytes of {@code data} from {@code offset}, as an unsigned 16-bit value. */
    public static int of(byte[] data, int offset, int length) {
        int crc = 0xFFFF;
        for (int i = offset; i < offset + length; i++) {
            crc = (crc >>> 8) ^ TABLE[(crc ^ data[i]) & 0xFF];
        }
        return crc;
    }

    /** Whether the first {@code length} bytes of {@code frame} end with their correct CRC (low byte first). */
    public static boolean isValidFrame(byte[] frame, int length) {
        return length >= 4 && of(frame, 0, length) == 0;
    }
}
