package robotworld.recording.mcap;

import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.ByteBuffer;
import java.util.LinkedHashMap;
import java.util.Map;

/** Reads MCAP's little-endian fields from a record's content, bounds-checked: a short field is a format error. */
final class RecordReader {

    private final byte[] bytes;
    private final int end;
    private final long fileOffset;
    private int position;

    /** Reads {@code bytes[from..to)}; {@code fileOffset} is where {@code bytes[from]} lies in the file, for messages. */
    RecordReader(byte[] bytes, int from, int to, long fileOffset) {
        this.bytes = bytes;
        this.position = from;
        this.end = to;
        this.fileOffset = fileOffset - from;
    }

    int position() {
        return position;
    }

    int remaining() {
        return end - position;
    }

    long offset() {
        return fileOffset + position;
    }

    private void need(long count, String what) throws McapFormatException {
        if (count < 0 || count > end - position) {
            throw new McapFormatException(offset(), what + " needs " + count + " bytes, the record has "
                    + (end - position) + " left");
        }
    }

    int u8() throws McapFormatException {
        need(1, "a uint8");
        return bytes[position++] & 0xFF;
    }

    int u16() throws McapFormatException {
        need(2, "a uint16");
        int value = (bytes[position] & 0xFF) | (bytes[position + 1] & 0xFF) << 8;
        position += 2;
        return value;
    }

    long u32() throws McapFormatException {
        need(4, "a uint32");
        long value = 0;
        for (int i = 0; i < 4; i++) {
            value |= (long) (bytes[position + i] & 0xFF) << (8 * i);
        }
        position += 4;
        return value;
    }

    long u64() throws McapFormatException {
        need(8, "a uint64");
        long value = 0;
        for (int i = 0; i < 8; i++) {
            value |= (long) (bytes[position + i] & 0xFF) << (8 * i);
        }
        position += 8;
        return value;
    }

    String string() throws McapFormatException {
        long length = u32();
        need(length, "a string");
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes, position, (int) length)).toString();
        } catch (CharacterCodingException e) {
            throw new McapFormatException(offset(), "a string is not valid UTF-8");
        }
        position += (int) length;
        return text;
    }

    byte[] bytes(long length) throws McapFormatException {
        need(length, "a byte field");
        byte[] copy = new byte[(int) length];
        System.arraycopy(bytes, position, copy, 0, (int) length);
        position += (int) length;
        return copy;
    }

    byte[] rest() {
        byte[] copy = new byte[end - position];
        System.arraycopy(bytes, position, copy, 0, copy.length);
        position = end;
        return copy;
    }

    Map<String, String> stringMap() throws McapFormatException {
        long length = u32();
        need(length, "a map");
        int stop = position + (int) length;
        Map<String, String> map = new LinkedHashMap<>();
        while (position < stop) {
            map.put(string(), string());
        }
        if (position != stop) {
            throw new McapFormatException(offset(), "a map's entries overrun its length");
        }
        return map;
    }

    Map<Integer, Long> u16u64Map() throws McapFormatException {
        long length = u32();
        need(length, "a map");
        if (length % 10 != 0) {
            throw new McapFormatException(offset(), "a map of uint16 to uint64 has " + length + " bytes");
        }
        Map<Integer, Long> map = new LinkedHashMap<>();
        for (long i = 0; i < length / 10; i++) {
            map.put(u16(), u64());
        }
        return map;
    }
}
