package robotworld.x10;

/** Hex helpers for tests: {@code Bytes.of("04 62")}. */
final class Bytes {

    private Bytes() {
    }

    static byte[] of(String hex) {
        String[] parts = hex.trim().isEmpty() ? new String[0] : hex.trim().split("\\s+");
        byte[] bytes = new byte[parts.length];
        for (int i = 0; i < parts.length; i++) {
            bytes[i] = (byte) Integer.parseInt(parts[i], 16);
        }
        return bytes;
    }
}
