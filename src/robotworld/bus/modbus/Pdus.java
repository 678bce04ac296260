package robotworld.bus.modbus;

/**
 * Request PDUs a client sends, and decoders for the data of their responses. Values are unsigned 16-bit words;
 * register and bit addresses are the 0-based PDU addresses.
 */
public final class Pdus {

    private Pdus() {
    }

    /** Read Device Identification, basic objects (code 01) from object 0. */
    public static byte[] readDeviceIdentification() {
        return readDeviceIdentification(0);
    }

    /** Read Device Identification, basic objects (code 01) from {@code objectId}: a follow-up after "more follows". */
    public static byte[] readDeviceIdentification(int objectId) {
        if (objectId < 0 || objectId > 0xFF) {
            throw new IllegalArgumentException("object id " + objectId + " is outside 0..255");
        }
        return new byte[] {(byte) FunctionCodes.ENCAPSULATED_INTERFACE, (byte) FunctionCodes.MEI_READ_DEVICE_ID, 0x01,
                (byte) objectId};
    }

    /** Report Server ID. */
    public static byte[] reportServerId() {
        return new byte[] {(byte) FunctionCodes.REPORT_SERVER_ID};
    }

    /** Diagnostics, Return Query Data, with any number of data words (1..125). */
    public static byte[] echo(int... words) {
        if (words.length < 1 || words.length > 125) {
            throw new IllegalArgumentException("echo 1..125 words, not " + words.length);
        }
        byte[] pdu = new byte[3 + 2 * words.length];
        pdu[0] = (byte) FunctionCodes.DIAGNOSTICS;
        for (int i = 0; i < words.length; i++) {
            checkWord(words[i]);
            pdu[3 + 2 * i] = (byte) (words[i] >>> 8);
            pdu[4 + 2 * i] = (byte) words[i];
        }
        return pdu;
    }

    /** Read {@code count} discrete inputs from {@code first}. */
    public static byte[] readDiscreteInputs(int first, int count) {
        return read(FunctionCodes.READ_DISCRETE_INPUTS, first, count, 2000);
    }

    /** Read {@code count} input registers from {@code first}. */
    public static byte[] readInputRegisters(int first, int count) {
        return read(FunctionCodes.READ_INPUT_REGISTERS, first, count, 125);
    }

    /** Read {@code count} holding registers from {@code first}. */
    public static byte[] readHoldingRegisters(int first, int count) {
        return read(FunctionCodes.READ_HOLDING_REGISTERS, first, count, 125);
    }

    /** Write one holding register. */
    public static byte[] writeSingleRegister(int register, int value) {
        checkWord(register);
        checkWord(value);
        return new byte[] {(byte) FunctionCodes.WRITE_SINGLE_REGISTER, (byte) (register >>> 8), (byte) register,
                (byte) (value >>> 8), (byte) value};
    }

    /** Write consecutive holding registers. */
    public static byte[] writeMultipleRegisters(int first, int[] values) {
        checkWord(first);
        if (values.length < 1 || values.length > 123) {
            throw new IllegalArgumentException("write 1..123 registers at once, not " + values.length);
        }
        byte[] pdu = new byte[6 + 2 * values.length];
        pdu[0] = (byte) FunctionCodes.WRITE_MULTIPLE_REGISTERS;
        pdu[1] = (byte) (first >>> 8);
        pdu[2] = (byte) first;
        pdu[3] = 0;
        pdu[4] = (byte) values.length;
        pdu[5] = (byte) (2 * values.length);
        for (int i = 0; i < values.length; i++) {
            checkWord(values[i]);
            pdu[6 + 2 * i] = (byte) (values[i] >>> 8);
            pdu[7 + 2 * i] = (byte) values[i];
        }
        return pdu;
    }

    /** The bits of a read-bits response ({@code fc count bytes...}), {@code count} of them, LSB first. */
    public static boolean[] decodeBits(byte[] response, int count) {
        int bytes = (count + 7) / 8;
        if (response.length != 2 + bytes || (response[1] & 0xFF) != bytes) {
            throw new MalformedPduException("expected " + bytes + " data bytes for " + count + " bits, got "
                    + RtuFrame.hex(response, response.length));
        }
        boolean[] bits = new boolean[count];
        for (int i = 0; i < count; i++) {
            bits[i] = (response[2 + i / 8] >> (i % 8) & 1) != 0;
        }
        return bits;
    }

    /** The words of a read-registers response ({@code fc count hi lo...}), {@code count} of them, unsigned. */
    public static int[] decodeRegisters(byte[] response, int count) {
        if (response.length != 2 + 2 * count || (response[1] & 0xFF) != 2 * count) {
            throw new MalformedPduException("expected " + count + " registers, got "
                    + RtuFrame.hex(response, response.length));
        }
        int[] words = new int[count];
        for (int i = 0; i < count; i++) {
            words[i] = (response[2 + 2 * i] & 0xFF) << 8 | response[3 + 2 * i] & 0xFF;
        }
        return words;
    }

    /** Checks that a write response echoes the request's address and value or count (functions 0x06, 0x10). */
    public static void checkWriteEcho(byte[] request, byte[] response) {
        if (response.length != 5 || !regionEquals(request, response, 5)) {
            throw new MalformedPduException("the write was not confirmed as sent: "
                    + RtuFrame.hex(response, response.length));
        }
    }

    /** Checks that a diagnostics response returns the request unaltered. */
    public static void checkEcho(byte[] request, byte[] response) {
        if (response.length != request.length || !regionEquals(request, response, request.length)) {
            throw new MalformedPduException("the echo came back altered: sent " + RtuFrame.hex(request, request.length)
                    + ", got " + RtuFrame.hex(response, response.length));
        }
    }

    /** A 16-bit register value as a signed number (two's complement), e.g. a motor speed. */
    public static int signed(int word) {
        return (short) word;
    }

    private static byte[] read(int function, int first, int count, int max) {
        checkWord(first);
        if (count < 1 || count > max) {
            throw new IllegalArgumentException("read 1.." + max + " items at once, not " + count);
        }
        return new byte[] {(byte) function, (byte) (first >>> 8), (byte) first, (byte) (count >>> 8), (byte) count};
    }

    private static boolean regionEquals(byte[] a, byte[] b, int length) {
        for (int i = 0; i < length; i++) {
            if (a[i] != b[i]) {
                return false;
            }
        }
        return true;
    }

    private static void checkWord(int value) {
        if (value < 0 || value > 0xFFFF) {
            throw new IllegalArgumentException("value " + value + " does not fit an unsigned 16-bit word");
        }
    }
}
