package robotworld.space.remote;

import java.io.Closeable;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.InterruptedIOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import robotworld.space.wire.Frames;
import robotworld.space.wire.Wire;

/**
 * One keep-alive HTTP/1.1 connection, used by one thread at a time: writes a request in a single write and reads
 * the answer (Content-Length or chunked) on the calling thread, with no thread hand-off, which is what keeps a
 * remote call close to the raw round trip. Also reads a streaming (chunked) answer line by line. A <em>framed</em>
 * connection carries operation requests as frames instead ({@link Frames}): the same bodies without the HTTP
 * request line and headers, which the server no longer has to parse.
 *
 * <p>Reads wait in slices so a waiting call can notice its thread's interrupt (and the connection being closed
 * from another thread) without making the socket unusable. A slice starts at 25 ms and doubles, up to 400 ms, while
 * an answer is awaited: a thousand callers waiting for long then cost a few wake-ups a second each, not forty.
 */
final class HttpConnection implements Closeable {

    /** How often a waiting read looks at its abort condition: at first, and at most. */
    private static final int SLICE_MILLIS = 25;
    private static final int LONGEST_SLICE_MILLIS = 400;
    private static final int MAX_HEADER_BYTES = 16 * 1024;

    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final String hostHeader;
    private byte[] buffer = new byte[8192];
    private int start;
    private int end;
    private volatile boolean closed;
    /** The current read slice, ms. */
    private int slice = SLICE_MILLIS;
    /** Whether this connection has completed an exchange before (a stale keep-alive connection fails at once). */
    boolean reused;
    /** Whether operations go as frames (after {@link #upgradeToFrames}); such a connection carries nothing else. */
    boolean framed;

    HttpConnection(String host, int port, int connectTimeoutMillis) throws IOException {
        socket = new Socket();
        try {
            socket.setTcpNoDelay(true);
            socket.setKeepAlive(true);
            socket.connect(new InetSocketAddress(host, port), connectTimeoutMillis);
            socket.setSoTimeout(SLICE_MILLIS);
            in = socket.getInputStream();
            out = socket.getOutputStream();
        } catch (IOException e) {
            socket.close();
            throw e;
        }
        hostHeader = host.contains(":") ? "[" + host + "]:" + port : host + ":" + port;
    }

    /** Why a read should stop waiting; checked between slices. */
    @FunctionalInterface
    interface Abort {
        /** @throws IOException (typically {@link InterruptedIOException}) to stop */
        void check() throws IOException;
    }

    /**
     * Sends an operation request: a frame on a framed connection, else {@code POST <path>/<operation>} with the
     * token and the take confirmations ({@code acks}, or null) as headers.
     */
    void sendOperation(Endpoint to, String operation, String acks, byte[] body, int bodyLength) throws IOException {
        if (!framed) {
            send("POST", to.path(operation), acks == null ? to.authorization()
                    : to.authorization() + Wire.ACK_HEADER + ": " + acks + "\r\n", body, bodyLength);
            return;
        }
        out.write(operationFrame(to, operation, acks, body, bodyLength));
        out.flush();
    }

    /** An operation request as a frame ({@link Frames}). */
    static byte[] operationFrame(Endpoint to, String operation, String acks, byte[] body, int bodyLength) {
        byte[] name = operation.getBytes(StandardCharsets.US_ASCII);
        byte[] token = to.token() == null ? new byte[0] : to.token().getBytes(StandardCharsets.UTF_8);
        byte[] ackBytes = acks == null ? new byte[0] : acks.getBytes(StandardCharsets.US_ASCII);
        if (ackBytes.length > Frames.MAX_ACKS_BYTES || token.length > Frames.MAX_TOKEN_BYTES || name.length > 255) {
            throw new IllegalArgumentException("a request frame's fields are too long");
        }
        int length = 1 + name.length + 2 + token.length + 2 + ackBytes.length + bodyLength;
        ByteBuffer frame = ByteBuffer.allocate(4 + length);
        frame.putInt(length).put((byte) name.length).put(name).putShort((short) token.length).put(token)
                .putShort((short) ackBytes.length).put(ackBytes).put(body, 0, bodyLength);
        return frame.array();
    }

    /** The HTTP/1.1 request that asks {@code to} to carry operations on the connection as frames. */
    static byte[] upgradeRequest(Endpoint to) {
        return ("GET " + to.basePath() + " HTTP/1.1\r\nHost: " + to.hostHeader() + "\r\nConnection: Upgrade\r\n"
                + "Upgrade: " + Frames.PROTOCOL + "\r\n" + to.authorization() + "\r\n")
                .getBytes(StandardCharsets.ISO_8859_1);
    }

    /**
     * Asks the server to carry operations on this connection as frames, with an HTTP/1.1 upgrade of
     * {@code GET <path>}.
     *
     * @return whether it did (101); otherwise the server answered the {@code GET} and the connection stays HTTP
     */
    boolean upgradeToFrames(Endpoint to, long deadline) throws IOException {
        out.write(upgradeRequest(to));
        out.flush();
        Head head = readHead(deadline, () -> { });
        if (head.status == 101) {
            framed = true;
            return true;
        }
        if (head.chunked) {
            readChunkedBody(deadline, () -> { });
        } else {
            readExactly(Math.max(0, head.contentLength), deadline, () -> { });
        }
        if (head.close) {
            close();
        }
        return false;
    }

    /** Sends a request; {@code headers} are extra lines, each ending in CRLF. */
    void send(String method, String path, String headers, byte[] body, int bodyLength) throws IOException {
        StringBuilder head = new StringBuilder(160 + headers.length());
        head.append(method).append(' ').append(path).append(" HTTP/1.1\r\nHost: ").append(hostHeader).append("\r\n");
        if (body != null) {
            head.append("Content-Type: application/json\r\nContent-Length: ").append(bodyLength).append("\r\n");
        }
        head.append(headers).append("\r\n");
        byte[] headBytes = head.toString().getBytes(StandardCharsets.ISO_8859_1);
        if (body == null) {
            out.write(headBytes);
        } else {
            byte[] message = Arrays.copyOf(headBytes, headBytes.length + bodyLength);
            System.arraycopy(body, 0, message, headBytes.length, bodyLength);
            out.write(message); // one write: no small-packet delays between head and body
        }
        out.flush();
    }

    /**
     * Reads a complete answer.
     *
     * @param deadline {@link System#nanoTime()} by which it must have arrived
     * @param abort    checked while waiting
     */
    Response receive(long deadline, Abort abort) throws IOException {
        shortSlices();
        if (framed) {
            return receiveFrame(deadline, abort);
        }
        Head head = readHead(deadline, abort);
        byte[] body;
        if (head.chunked) {
            body = readChunkedBody(deadline, abort);
        } else if (head.contentLength >= 0) {
            body = readExactly(head.contentLength, deadline, abort);
        } else {
            throw new IOException("answer without a length");
        }
        if (head.close) {
            close();
        }
        reused = true;
        return new Response(head.status, body);
    }

    private Response receiveFrame(long deadline, Abort abort) throws IOException {
        while (end - start < 7) {
            fill(deadline, abort);
        }
        if (buffer[start] == 'H' && buffer[start + 1] == 'T' && buffer[start + 2] == 'T' && buffer[start + 3] == 'P') {
            throw new IOException("the server answered a frame in HTTP: it does not take frames");
        }
        int length = ByteBuffer.wrap(buffer, start, 4).getInt();
        if (length < 3) {
            throw new IOException("not an answer frame (length " + Integer.toUnsignedString(length) + ")");
        }
        int status = ((buffer[start + 4] & 0xff) << 8) | (buffer[start + 5] & 0xff);
        int flags = buffer[start + 6];
        start += 7;
        byte[] body = readExactly(Integer.toUnsignedLong(length) - 3, deadline, abort);
        if ((flags & Frames.CLOSING) != 0) {
            close();
        }
        reused = true;
        return new Response(status, body);
    }

    /** Reads the head of a streaming answer; the body then comes through {@link #readLine}. */
    int receiveStreamHead(long deadline, Abort abort) throws IOException {
        Head head = readHead(deadline, abort);
        if (head.status == 200 && !head.chunked) {
            throw new IOException("the notification stream is not chunked");
        }
        if (head.status != 200) {
            body = head.chunked ? readChunkedBody(deadline, abort) : readExactly(Math.max(0, head.contentLength),
                    deadline, abort);
        }
        return head.status;
    }

    /** The body of a refused stream request (after {@link #receiveStreamHead} returned another status than 200). */
    byte[] body;

    private int chunkLeft;

    /**
     * The next line of a chunked streaming answer, without its newline; null at the end of the stream.
     *
     * @param idleDeadline by when something must arrive
     */
    byte[] readLine(long idleDeadline, Abort abort) throws IOException {
        shortSlices();
        java.io.ByteArrayOutputStream line = null;
        while (true) {
            if (chunkLeft == 0) {
                if (chunkDone) {
                    readCrlf(idleDeadline, abort);
                    chunkDone = false;
                }
                long size = chunkSize(idleDeadline, abort);
                if (size == 0) {
                    readCrlf(idleDeadline, abort); // end of the stream: trailers are not used
                    return null;
                }
                chunkLeft = (int) size;
            }
            if (start == end) {
                fill(idleDeadline, abort);
            }
            int available = Math.min(end - start, chunkLeft);
            int newline = indexOf((byte) '\n', start, start + available);
            int take = newline < 0 ? available : newline - start + 1;
            if (line == null && newline >= 0) {
                byte[] result = Arrays.copyOfRange(buffer, start, newline);
                consume(take);
                return result;
            }
            if (line == null) {
                line = new java.io.ByteArrayOutputStream(Math.max(64, take * 2));
            }
            line.write(buffer, start, newline < 0 ? take : take - 1);
            consume(take);
            if (newline >= 0) {
                return line.toByteArray();
            }
            if (line.size() > 16 * 1024 * 1024) {
                throw new IOException("a notification line is too long");
            }
        }
    }

    /** Starts a new wait with short slices. */
    private void shortSlices() throws IOException {
        if (slice != SLICE_MILLIS) {
            slice = SLICE_MILLIS;
            socket.setSoTimeout(SLICE_MILLIS);
        }
    }

    private void consume(int count) {
        start += count;
        chunkLeft -= count;
        chunkDone = chunkLeft == 0;
    }

    /** A chunk was read up to its end; its CRLF is still to come. */
    private boolean chunkDone;

    // ---- parsing ----

    private record Head(int status, long contentLength, boolean chunked, boolean close) {
    }

    private Head readHead(long deadline, Abort abort) throws IOException {
        int headEnd;
        while ((headEnd = indexOfHeadEnd()) < 0) {
            if (end - start > MAX_HEADER_BYTES) {
                throw new IOException("answer head too long");
            }
            fill(deadline, abort);
        }
        String head = new String(buffer, start, headEnd - start, StandardCharsets.ISO_8859_1);
        start = headEnd + 4;
        String[] lines = head.split("\r\n");
        String[] statusLine = lines[0].split(" ", 3);
        if (statusLine.length < 2 || !statusLine[0].startsWith("HTTP/1.")) {
            throw new IOException("not an HTTP answer: " + lines[0]);
        }
        int status;
        try {
            status = Integer.parseInt(statusLine[1]);
        } catch (NumberFormatException e) {
            throw new IOException("bad status line: " + lines[0]);
        }
        long length = -1;
        boolean chunked = false;
        boolean close = statusLine[0].equals("HTTP/1.0");
        for (int i = 1; i < lines.length; i++) {
            String line = lines[i];
            int colon = line.indexOf(':');
            if (colon <= 0) {
                continue;
            }
            String name = line.substring(0, colon).trim();
            String value = line.substring(colon + 1).trim();
            if (name.equalsIgnoreCase("Content-Length")) {
                length = Long.parseLong(value);
            } else if (name.equalsIgnoreCase("Transfer-Encoding")) {
                chunked = value.toLowerCase(java.util.Locale.ROOT).contains("chunked");
            } else if (name.equalsIgnoreCase("Connection")) {
                close = value.equalsIgnoreCase("close");
            }
        }
        return new Head(status, length, chunked, close);
    }

    private int indexOfHeadEnd() {
        for (int i = start; i + 3 < end; i++) {
            if (buffer[i] == '\r' && buffer[i + 1] == '\n' && buffer[i + 2] == '\r' && buffer[i + 3] == '\n') {
                return i;
            }
        }
        return -1;
    }

    private byte[] readExactly(long length, long deadline, Abort abort) throws IOException {
        if (length > Integer.MAX_VALUE - 16) {
            throw new IOException("answer too large: " + length + " bytes");
        }
        byte[] body = new byte[(int) length];
        int filled = Math.min(end - start, body.length);
        System.arraycopy(buffer, start, body, 0, filled);
        start += filled;
        while (filled < body.length) {
            int read = readSliced(body, filled, body.length - filled, deadline, abort);
            filled += read;
        }
        return body;
    }

    private byte[] readChunkedBody(long deadline, Abort abort) throws IOException {
        java.io.ByteArrayOutputStream body = new java.io.ByteArrayOutputStream();
        while (true) {
            long size = chunkSize(deadline, abort);
            if (size == 0) {
                readCrlf(deadline, abort);
                return body.toByteArray();
            }
            byte[] chunk = readExactly(size, deadline, abort);
            body.write(chunk, 0, chunk.length);
            readCrlf(deadline, abort);
        }
    }

    private long chunkSize(long deadline, Abort abort) throws IOException {
        int lineEnd;
        while ((lineEnd = indexOf((byte) '\n', start, end)) < 0) {
            if (end - start > 1024) {
                throw new IOException("bad chunk header");
            }
            fill(deadline, abort);
        }
        String line = new String(buffer, start, lineEnd - start, StandardCharsets.ISO_8859_1).trim();
        start = lineEnd + 1;
        int semicolon = line.indexOf(';');
        try {
            return Long.parseLong(semicolon < 0 ? line : line.substring(0, semicolon), 16);
        } catch (NumberFormatException e) {
            throw new IOException("bad chunk size: " + line);
        }
    }

    private void readCrlf(long deadline, Abort abort) throws IOException {
        while (end - start < 2) {
            fill(deadline, abort);
        }
        if (buffer[start] != '\r' || buffer[start + 1] != '\n') {
            throw new IOException("missing CRLF after a chunk");
        }
        start += 2;
    }

    private int indexOf(byte value, int from, int to) {
        for (int i = from; i < to; i++) {
            if (buffer[i] == value) {
                return i;
            }
        }
        return -1;
    }

    /** Reads more bytes into the buffer (compacting or growing it first). */
    private void fill(long deadline, Abort abort) throws IOException {
        if (start > 0) {
            System.arraycopy(buffer, start, buffer, 0, end - start);
            end -= start;
            start = 0;
        }
        if (end == buffer.length) {
            buffer = Arrays.copyOf(buffer, buffer.length * 2);
        }
        end += readSliced(buffer, end, buffer.length - end, deadline, abort);
    }

    private int readSliced(byte[] into, int offset, int length, long deadline, Abort abort) throws IOException {
        while (true) {
            try {
                int read = in.read(into, offset, length);
                if (read < 0) {
                    throw new EOFException("the server closed the connection");
                }
                return read;
            } catch (SocketTimeoutException sliceOver) {
                if (closed) {
                    throw new IOException("connection closed");
                }
                abort.check();
                long left = deadline - System.nanoTime();
                if (left > 0) {
                    slice = Math.min(LONGEST_SLICE_MILLIS, slice * 2);
                    socket.setSoTimeout((int) Math.max(1, Math.min(slice, left / 1_000_000 + 1)));
                } else {
                    throw new SocketTimeoutException("no answer in time");
                }
            }
        }
    }

    boolean isOpen() {
        return !closed;
    }

    /** Whether bytes of an answer have been buffered (a failed exchange that had started answering). */
    boolean hasBufferedInput() {
        return end > start;
    }

    @Override
    public void close() {
        closed = true;
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    /** A complete answer. */
    record Response(int status, byte[] body) {
    }
}
