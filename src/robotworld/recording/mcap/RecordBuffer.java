package robotworld.recording.mcap;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Map;

/** A growable byte buffer with MCAP's little-endian serialization (integers, strings, maps, records). */
final class RecordBuffer {

    private byte[] bytes;
    private int size;

    RecordBuffer(int capacity) {
        bytes = new byte[Math.max(16, capacity)];
    }

    int size() {
        return size;
    }

    byte[] array() {
        return bytes;
    }

    void clear() {
        size = 0;
    }

    private void ensure(int more) {
        if (size + more > bytes.length) {
            long wanted = Math.max((long) bytes.length * 2, (long) size + more);
            if (wanted > Integer.MAX_VALUE - 16) {
                throw new IllegalStateException("record buffer over 2 GiB");
            }
            bytes = Arrays.copyOf(bytes, (int) wanted);
        }
    }

    RecordBuffer u8(int value) {
        ensure(1);
        bytes[size++] = (byte) value;
        return this;
    }

    RecordBuffer u16(int value) {
        ensure(2);
        bytes[size++] = (byte) value;
        bytes[size++] = (byte) (value >>> 8);
        return this;
    }

    RecordBuffer u32(long value) {
        ensure(4);
        for (int i = 0; i < 4; i++) {
            bytes[size++] = (byte) (value >>> (8 * i));
        }
        return this;
    }

    RecordBuffer u64(long value) {
        ensure(8);
        for (int i = 0; i < 8; i++) {
            bytes[size++] = (byte) (value >>> (8 * i));
        }
        return this;
    }

    RecordBuffer raw(byte[] data, int offset, int length) {
        ensure(length);
        System.arraycopy(data, offset, bytes, size, length);
        size += length;
        return this;
    }

    RecordBuffer raw(byte[] data) {
        return raw(data, 0, data.length);
    }

    /** A String: uint32 byte length, then UTF-8. */
    RecordBuffer string(String text) {
        byte[] utf8 = text.getBytes(StandardCharsets.UTF_8);
        u32(utf8.length);
        return raw(utf8);
    }

    /** A {@code Map<string, string>}: uint32 byte length, then key and value strings. */
    RecordBuffer stringMap(Map<String, String> map) {
        int lengthAt = size;
        u32(0);
        int start = size;
        map.entrySet().stream().sorted(Map.Entry.comparingByKey()).forEach(e -> string(e.getKey()).string(e.getValue()));
        patchU32(lengthAt, size - start);
        return this;
    }

    /** A {@code Map<uint16, uint64>}, keys ascending. */
    RecordBuffer u16u64Map(Map<Integer, Long> map) {
        u32(map.size() * 10L);
        map.entrySet().stream().sorted(Map.Entry.comparingByKey()).forEach(e -> u16(e.getKey()).u64(e.getValue()));
        return this;
    }

    void patchU32(int at, long value) {
        for (int i = 0; i < 4; i++) {
            bytes[at + i] = (byte) (value >>> (8 * i));
        }
    }

    void patchU64(int at, long value) {
        for (int i = 0; i < 8; i++) {
            bytes[at + i] = (byte) (value >>> (8 * i));
        }
    }

    /** Starts a record: opcode and a length to be patched by {@link #endRecord(int)}; returns where it starts. */
    int startRecord(int opcode) {
        int start = size;
        u8(opcode);
        u64(0);
        return start;
    }

    void endRecord(int start) {
        patchU64(start + 1, size - start - 9L);
    }
}
