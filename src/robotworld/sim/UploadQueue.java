package robotworld.sim;

import java.util.ArrayDeque;
import java.util.Deque;
import robotworld.x10.X10Constants;

/**
 * What the simulated interface heard on the power line and must upload: buffers of at most eight data bytes, each
 * uploaded as {@code size mask data...}. A message that does not fit in the current buffer starts a new one (the
 * real interface would drop it; the simulator keeps it, so tests do not lose events). Thread-safe.
 */
final class UploadQueue {

    private static final int MAX_DATA = X10Constants.CM11A_MAX_UPLOAD_SIZE - 1;

    private final Deque<Buffer> buffers = new ArrayDeque<>();

    private static final class Buffer {
        final byte[] data = new byte[MAX_DATA];
        int mask;
        int length;

        boolean fits(int count) {
            return length + count <= MAX_DATA;
        }

        byte[] upload() {
            byte[] upload = new byte[2 + length];
            upload[0] = (byte) (1 + length);
            upload[1] = (byte) mask;
            System.arraycopy(data, 0, upload, 2, length);
            return upload;
        }
    }

    /**
     * Adds one power-line message.
     *
     * @param bytes the data bytes in order
     * @param functionFlags per data byte, whether it is a function byte
     */
    synchronized void add(byte[] bytes, boolean[] functionFlags) {
        if (bytes.length > MAX_DATA) {
            throw new IllegalArgumentException("a message has at most 8 bytes");
        }
        Buffer buffer = buffers.peekLast();
        if (buffer == null || !buffer.fits(bytes.length)) {
            buffer = new Buffer();
            buffers.addLast(buffer);
        }
        for (int i = 0; i < bytes.length; i++) {
            if (functionFlags[i]) {
                buffer.mask |= 1 << buffer.length;
            }
            buffer.data[buffer.length++] = bytes[i];
        }
    }

    synchronized boolean isEmpty() {
        return buffers.isEmpty();
    }

    /** The oldest buffer as uploaded after 0xC3 ({@code size mask data...}), removed; null when empty. */
    synchronized byte[] take() {
        Buffer buffer = buffers.pollFirst();
        return buffer == null ? null : buffer.upload();
    }

    synchronized void clear() {
        buffers.clear();
    }
}
