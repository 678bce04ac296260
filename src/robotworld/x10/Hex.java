package robotworld.x10;

/** Formats bytes as upper-case hex separated by spaces, the way protocol documents show them. */
public final class Hex {

    private Hex() {
    }

    /** e.g. {@code 04 62}. */
    public static String of(byte[] bytes) {
        return of(bytes, 0, bytes.length);
    }

    /** {@code length} bytes from {@code offset}. */
    public static String of(byte[] bytes, int offset, int length) {
        StringBuilder text = new StringBuilder(length * 3);
        for (int i = offset; i < offset + length; i++) {
            if (text.length() > 0) {
                text.append(' ');
            }
            text.append(String.format("%02X", bytes[i] & 0xFF));
        }
        return text.toString();
    }

    /** One byte value 0..255, e.g. {@code 5A}. */
    public static String of(int value) {
        return String.format("%02X", value & 0xFF);
    }
}
