package robotworld.x10;

import robotworld.bus.SerialSettings;

/**
 * The codes of the X10 protocol and of the CM11A serial interface as byte values, so that frames can be written
 * and read by name. House and unit codes share one 4-bit code table; function codes are the low nibble of a
 * function byte whose high nibble is the house code.
 */
public final class X10Constants {

    private X10Constants() {
    }

    // ----- house codes A..P (high nibble of an address or function byte) -----
    public static final byte HOUSE_A = 0x6;
    public static final byte HOUSE_B = 0xE;
    public static final byte HOUSE_C = 0x2;
    public static final byte HOUSE_D = 0xA;
    public static final byte HOUSE_E = 0x1;
    public static final byte HOUSE_F = 0x9;
    public static final byte HOUSE_G = 0x5;
    public static final byte HOUSE_H = 0xD;
    public static final byte HOUSE_I = 0x7;
    public static final byte HOUSE_J = 0xF;
    public static final byte HOUSE_K = 0x3;
    public static final byte HOUSE_L = 0xB;
    public static final byte HOUSE_M = 0x0;
    public static final byte HOUSE_N = 0x8;
    public static final byte HOUSE_O = 0x4;
    public static final byte HOUSE_P = 0xC;

    // ----- unit codes 1..16 (low nibble of an address byte); the same table as the house codes -----
    public static final byte UNIT_1 = 0x6;
    public static final byte UNIT_2 = 0xE;
    public static final byte UNIT_3 = 0x2;
    public static final byte UNIT_4 = 0xA;
    public static final byte UNIT_5 = 0x1;
    public static final byte UNIT_6 = 0x9;
    public static final byte UNIT_7 = 0x5;
    public static final byte UNIT_8 = 0xD;
    public static final byte UNIT_9 = 0x7;
    public static final byte UNIT_10 = 0xF;
    public static final byte UNIT_11 = 0x3;
    public static final byte UNIT_12 = 0xB;
    public static final byte UNIT_13 = 0x0;
    public static final byte UNIT_14 = 0x8;
    public static final byte UNIT_15 = 0x4;
    public static final byte UNIT_16 = 0xC;

    /** Code of letter/number index 0..15 (A/1 .. P/16). */
    static final byte[] CODE_TABLE = {
        HOUSE_A, HOUSE_B, HOUSE_C, HOUSE_D, HOUSE_E, HOUSE_F, HOUSE_G, HOUSE_H,
        HOUSE_I, HOUSE_J, HOUSE_K, HOUSE_L, HOUSE_M, HOUSE_N, HOUSE_O, HOUSE_P,
    };

    // ----- function codes (low nibble of a function byte) -----
    public static final byte FUNCTION_ALL_UNITS_OFF = 0x0;
    public static final byte FUNCTION_ALL_LIGHTS_ON = 0x1;
    public static final byte FUNCTION_ON = 0x2;
    public static final byte FUNCTION_OFF = 0x3;
    public static final byte FUNCTION_DIM = 0x4;
    public static final byte FUNCTION_BRIGHT = 0x5;
    public static final byte FUNCTION_ALL_LIGHTS_OFF = 0x6;
    public static final byte FUNCTION_EXTENDED_CODE = 0x7;
    public static final byte FUNCTION_HAIL_REQUEST = 0x8;
    public static final byte FUNCTION_HAIL_ACKNOWLEDGE = 0x9;
    public static final byte FUNCTION_PRESET_DIM_1 = 0xA;
    public static final byte FUNCTION_PRESET_DIM_2 = 0xB;
    public static final byte FUNCTION_EXTENDED_DATA_TRANSFER = 0xC;
    public static final byte FUNCTION_STATUS_ON = 0xD;
    public static final byte FUNCTION_STATUS_OFF = 0xE;
    public static final byte FUNCTION_STATUS_REQUEST = 0xF;

    // ----- header byte of a host-to-CM11A transmission: bits 7-3 dims, bit 2 sync, bit 1 F/A, bit 0 E/S -----
    /** Bit 2: always set in a transmission header, so the interface can tell headers from other bytes. */
    public static final int HEADER_SYNC_BIT = 0x04;
    /** Bit 1: the code byte is a function (set) or an address (clear). */
    public static final int HEADER_FUNCTION_BIT = 0x02;
    /** Bit 0: an extended transmission (header, code, unit, data, command). */
    public static final int HEADER_EXTENDED_BIT = 0x01;
    /** Bits 7-3 carry the number of dim/bright steps. */
    public static final int HEADER_DIMS_SHIFT = 3;
    /** Header of a plain address transmission. */
    public static final int HEADER_ADDRESS = HEADER_SYNC_BIT;
    /** Header of a function transmission without dim steps. */
    public static final int HEADER_FUNCTION = HEADER_SYNC_BIT | HEADER_FUNCTION_BIT;
    /** Header of an extended code transmission. */
    public static final int HEADER_EXTENDED = HEADER_SYNC_BIT | HEADER_FUNCTION_BIT | HEADER_EXTENDED_BIT;

    /** Dim and bright amounts are given in 22 steps; 22 steps are the full range. */
    public static final int DIM_STEPS_FULL_RANGE = 22;
    /** Brightness changes in an upload are given in 210 levels; 210 is the full range. */
    public static final int UPLOAD_LEVELS_FULL_RANGE = 210;

    // ----- CM11A serial protocol bytes -----
    /** Host to interface: the checksum was right, transmit now. */
    public static final int CM11A_ACK = 0x00;
    /** Interface to host: transmission done, ready for the next one. */
    public static final int CM11A_READY = 0x55;
    /** Interface to host, once a second: data from the power line is waiting to be uploaded. */
    public static final int CM11A_POLL = 0x5A;
    /** Host to interface: answer to {@link #CM11A_POLL}, send the upload buffer now. */
    public static final int CM11A_POLL_ACK = 0xC3;
    /** Interface to host, once a second after a power failure: send the clock. */
    public static final int CM11A_POWER_FAIL_POLL = 0xA5;
    /** Host to interface: header of the six clock bytes that answer {@link #CM11A_POWER_FAIL_POLL}. */
    public static final int CM11A_SET_CLOCK = 0x9B;
    /** Host to interface: request the 14-byte status. */
    public static final int CM11A_STATUS_REQUEST = 0x8B;
    /** Host to interface: enable the serial ring signal. */
    public static final int CM11A_RING_ENABLE = 0xEB;
    /** Host to interface: disable the serial ring signal. */
    public static final int CM11A_RING_DISABLE = 0xDB;
    /** Host to interface: start of an EEPROM (timer/macro) download block. */
    public static final int CM11A_EEPROM_DOWNLOAD = 0xFB;
    /** Number of bytes the interface sends after {@link #CM11A_STATUS_REQUEST}. */
    public static final int CM11A_STATUS_LENGTH = 14;
    /** Number of clock bytes after {@link #CM11A_SET_CLOCK}. */
    public static final int CM11A_CLOCK_LENGTH = 6;
    /** Largest upload size byte: the function/address mask plus eight data bytes. */
    public static final int CM11A_MAX_UPLOAD_SIZE = 9;

    /** The CM11A's serial line: 4800 baud, 8 data bits, no parity, 1 stop bit. */
    public static final SerialSettings CM11A_SERIAL = SerialSettings.eightNoneOne(4800);

    /**
     * The 4-bit code of unit 1..16.
     *
     * @throws IllegalArgumentException outside 1..16
     */
    public static byte unitCode(int unit) {
        if (unit < 1 || unit > 16) {
            throw new IllegalArgumentException("X10 unit codes are 1..16, was " + unit);
        }
        return CODE_TABLE[unit - 1];
    }

    /** The unit 1..16 whose 4-bit code is {@code code} (only the low nibble counts). */
    public static int unitOfCode(int code) {
        int nibble = code & 0x0F;
        for (int i = 0; i < CODE_TABLE.length; i++) {
            if (CODE_TABLE[i] == nibble) {
                return i + 1;
            }
        }
        throw new AssertionError("the code table covers every nibble");
    }

    /** Whether {@code value} (0..255) can be mistaken for an unsolicited poll of the interface. */
    public static boolean looksLikePoll(int value) {
        return value == CM11A_POLL || value == CM11A_POWER_FAIL_POLL;
    }

    /**
     * Preset Dim's level 0..31 from the code byte's high nibble (its four low bits in reversed order: the nibbles of
     * house codes M, N, O, P, C, D, A, B, ... are levels 0, 1, 2, 3, ...) and the function (Preset Dim 2 adds 16).
     */
    public static int presetDimLevel(int nibble, boolean presetDim2) {
        return reverseNibble(nibble) + (presetDim2 ? 16 : 0);
    }

    /** The high nibble that carries the four low bits of Preset Dim level {@code level} (0..31). */
    public static int presetDimNibble(int level) {
        return reverseNibble(level & 0x0F);
    }

    private static int reverseNibble(int nibble) {
        return (nibble & 1) << 3 | (nibble & 2) << 1 | (nibble & 4) >> 1 | (nibble & 8) >> 3;
    }
}
