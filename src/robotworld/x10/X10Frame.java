package robotworld.x10;

import java.util.Arrays;

/**
 * One host-to-CM11A transmission: a header byte and a code byte (address or function), or for extended code a
 * header, a code, a unit, a data and a command byte. The interface echoes the sum of these bytes as checksum.
 *
 * <p>A checksum of 0x5A or 0xA5 cannot be told apart from a poll of the interface. Where the dim-step bits of the
 * header mean nothing (addresses, functions other than Dim/Bright) the factory methods set one dim step, which
 * the interface ignores but which moves the checksum off the poll values; heyu does the same (header 0x0C for
 * address G1). Dim/Bright and extended frames cannot be changed this way; the controller handles those.
 */
public final class X10Frame {

    private final byte[] bytes;
    private final String description;

    private X10Frame(byte[] bytes, String description) {
        this.bytes = bytes;
        this.description = description;
    }

    /** Address frame for {@code address}, e.g. A3 is {@code 04 62}. */
    public static X10Frame address(X10Address address) {
        return unambiguous(X10Constants.HEADER_ADDRESS, address.code(), "address " + address);
    }

    /** Function frame for a function without dim steps, e.g. A On is {@code 06 62}. */
    public static X10Frame function(HouseCode house, X10Function function) {
        return function(house, function, 0);
    }

    /**
     * Function frame; {@code dimSteps} (0..22) only means something for Dim and Bright.
     *
     * @throws IllegalArgumentException when dimSteps is outside 0..22 or given for another function
     */
    public static X10Frame function(HouseCode house, X10Function function, int dimSteps) {
        if (dimSteps < 0 || dimSteps > X10Constants.DIM_STEPS_FULL_RANGE) {
            throw new IllegalArgumentException("dim steps must be 0..22, was " + dimSteps);
        }
        if (function == X10Function.EXTENDED_CODE) {
            throw new IllegalArgumentException("extended code needs a unit, data and command: use extended()");
        }
        int code = house.code() << 4 | function.code();
        if (!function.usesDimSteps()) {
            if (dimSteps != 0) {
                throw new IllegalArgumentException(function + " takes no dim steps");
            }
            return unambiguous(X10Constants.HEADER_FUNCTION, code, house.name() + " " + function);
        }
        int header = dimSteps << X10Constants.HEADER_DIMS_SHIFT | X10Constants.HEADER_FUNCTION;
        return new X10Frame(new byte[] {(byte) header, (byte) code},
                house.name() + " " + function + " " + dimSteps + "/22");
    }

    /**
     * Extended code frame (type 0x07 header): {@code 07 <house|7> <unit> <data> <command>}.
     *
     * @param data 0..255
     * @param command 0..255
     */
    public static X10Frame extended(X10Address address, int data, int command) {
        if (data < 0 || data > 0xFF || command < 0 || command > 0xFF) {
            throw new IllegalArgumentException("extended data and command are bytes 0..255");
        }
        int code = address.house().code() << 4 | X10Constants.FUNCTION_EXTENDED_CODE;
        byte[] bytes = {(byte) X10Constants.HEADER_EXTENDED, (byte) code,
            X10Constants.unitCode(address.unit()), (byte) data, (byte) command};
        return new X10Frame(bytes, String.format("extended %s data %02X command %02X", address, data, command));
    }

    private static X10Frame unambiguous(int header, int code, String description) {
        if (X10Constants.looksLikePoll((header + code) & 0xFF)) {
            header |= 1 << X10Constants.HEADER_DIMS_SHIFT;
        }
        return new X10Frame(new byte[] {(byte) header, (byte) code}, description);
    }

    /** The bytes to send (a copy). */
    public byte[] bytes() {
        return bytes.clone();
    }

    /** The checksum the interface must echo: the sum of all bytes, modulo 256. */
    public int checksum() {
        int sum = 0;
        for (byte b : bytes) {
            sum += b & 0xFF;
        }
        return sum & 0xFF;
    }

    /** Whether the checksum equals a poll byte, so an echo cannot be told from a poll at first sight. */
    public boolean hasAmbiguousChecksum() {
        return X10Constants.looksLikePoll(checksum());
    }

    /** Human-readable meaning, e.g. "address A3" or "A Dim 11/22". */
    public String description() {
        return description;
    }

    /** The bytes as hex, e.g. "04 62". */
    public String hex() {
        return Hex.of(bytes);
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof X10Frame frame && Arrays.equals(bytes, frame.bytes);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(bytes);
    }

    @Override
    public String toString() {
        return hex() + " (" + description + ")";
    }
}
