package robotworld.recording.mcap;

import com.github.luben.zstd.Zstd;
import com.github.luben.zstd.ZstdException;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import net.jpountz.lz4.LZ4FrameInputStream;

/**
 * Opens a chunk's records as the MCAP specification compresses them: {@code ""} (none), {@code "zstd"} (a
 * Zstandard frame) and {@code "lz4"} (an LZ4 frame). The reference Python writer compresses with zstd unless told
 * otherwise, so a reader of other programs' files needs both.
 */
final class ChunkCompression {

    private ChunkCompression() {
    }

    /**
     * The {@code uncompressedSize} bytes that {@code data[from, from + length)} holds.
     *
     * @param offset where the chunk lies in the file, for messages
     * @throws McapFormatException for an unknown compression, or data that does not give exactly that many bytes
     */
    static byte[] open(String compression, byte[] data, int from, int length, long uncompressedSize, long offset)
            throws McapFormatException {
        if (uncompressedSize < 0 || uncompressedSize > McapReader.MAX_RECORD) {
            throw new McapFormatException(offset, "a chunk says it holds " + uncompressedSize
                    + " bytes, beyond what this reader takes");
        }
        return switch (compression) {
            case "zstd" -> zstd(data, from, length, (int) uncompressedSize, offset);
            case "lz4" -> lz4(data, from, length, (int) uncompressedSize, offset);
            default -> throw new McapFormatException(offset, "this chunk is compressed with '" + compression
                    + "', which this reader does not read (it reads zstd, lz4 and uncompressed chunks)");
        };
    }

    private static byte[] zstd(byte[] data, int from, int length, int size, long offset) throws McapFormatException {
        byte[] records = new byte[size];
        long result;
        try {
            result = Zstd.decompressByteArray(records, 0, size, data, from, length);
        } catch (ZstdException e) {
            throw new McapFormatException(offset, "a zstd chunk cannot be decompressed: " + e.getMessage());
        } catch (LinkageError e) {
            // zstd-jni carries native code for the common platforms only
            throw new McapFormatException(offset, "this chunk is compressed with zstd, and zstd cannot be loaded on"
                    + " this platform (" + e.getMessage() + "); rewrite the file with uncompressed chunks elsewhere, e.g."
                    + " with the mcap command-line tool");
        }
        if (Zstd.isError(result)) {
            throw new McapFormatException(offset, "a zstd chunk cannot be decompressed: " + Zstd.getErrorName(result));
        }
        if (result != size) {
            throw new McapFormatException(offset, "a zstd chunk gives " + result + " bytes, it says it holds " + size);
        }
        return records;
    }

    private static byte[] lz4(byte[] data, int from, int length, int size, long offset) throws McapFormatException {
        try (InputStream in = new LZ4FrameInputStream(new ByteArrayInputStream(data, from, length))) {
            byte[] records = in.readNBytes(size);
            if (records.length != size || in.read() != -1) {
                throw new McapFormatException(offset, "an lz4 chunk does not hold the " + size + " bytes it says");
            }
            return records;
        } catch (McapFormatException e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            throw new McapFormatException(offset, "an lz4 chunk cannot be decompressed: " + e.getMessage());
        }
    }
}
