package robotworld.space.server;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;

/**
 * Sends hand-made HTTP/1.1 requests (any method, headers, body, even lies in Content-Length) on a fresh
 * connection and reads the whole answer: what a hostile or broken client would do.
 */
final class RawHttp {

    private RawHttp() {
    }

    /** An answer: status and body text. */
    record Answer(int status, String head, String body) {
    }

    static Answer post(URI space, String path, String contentType, String body, String... headers) throws IOException {
        byte[] bytes = body.getBytes(StandardCharsets.UTF_8);
        StringBuilder head = new StringBuilder("POST " + space.getPath() + path + " HTTP/1.1\r\n");
        if (contentType != null) {
            head.append("Content-Type: ").append(contentType).append("\r\n");
        }
        head.append("Content-Length: ").append(bytes.length).append("\r\n");
        for (String header : headers) {
            head.append(header).append("\r\n");
        }
        return send(space, head.toString(), bytes);
    }

    /** Sends a request head (without the blank line, which is added) and a body as given. */
    static Answer send(URI space, String head, byte[] body) throws IOException {
        return sendFrom(null, space, head, body);
    }

    /** As {@link #send}, from the local address {@code from} (null: any). */
    static Answer sendFrom(java.net.InetAddress from, URI space, String head, byte[] body) throws IOException {
        try (Socket socket = new Socket()) {
            if (from != null) {
                socket.bind(new java.net.InetSocketAddress(from, 0));
            }
            socket.connect(new java.net.InetSocketAddress(space.getHost(), space.getPort()), 10_000);
            socket.setSoTimeout(10_000);
            OutputStream out = socket.getOutputStream();
            String full = head + (head.contains("\r\nHost:") ? "" : "Host: " + space.getHost() + "\r\n")
                    + "Connection: close\r\n\r\n";
            out.write(full.getBytes(StandardCharsets.ISO_8859_1));
            try {
                out.write(body);
                out.flush();
                socket.shutdownOutput(); // no more body: a server waiting for more sees the end
            } catch (IOException serverStoppedReading) {
                // the server may answer (413) and close before reading a large body: read its answer anyway
            }
            return read(socket.getInputStream());
        }
    }

    private static Answer read(InputStream in) throws IOException {
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        byte[] buffer = new byte[8192];
        int read;
        try {
            while ((read = in.read(buffer)) >= 0) {
                all.write(buffer, 0, read);
            }
        } catch (IOException reset) {
            // a connection reset after the answer arrived is fine
        }
        String text = all.toString(StandardCharsets.ISO_8859_1);
        int headEnd = text.indexOf("\r\n\r\n");
        if (headEnd < 0) {
            throw new IOException("no HTTP answer: '" + text + "'");
        }
        String head = text.substring(0, headEnd);
        String body = text.substring(headEnd + 4);
        if (head.toLowerCase(java.util.Locale.ROOT).contains("transfer-encoding: chunked")) {
            body = dechunk(body);
        }
        int status = Integer.parseInt(head.split(" ", 3)[1]);
        return new Answer(status, head, body);
    }

    private static String dechunk(String chunked) {
        StringBuilder out = new StringBuilder();
        int at = 0;
        while (at < chunked.length()) {
            int lineEnd = chunked.indexOf("\r\n", at);
            if (lineEnd < 0) {
                break;
            }
            int size = Integer.parseInt(chunked.substring(at, lineEnd).trim(), 16);
            if (size == 0) {
                break;
            }
            out.append(chunked, lineEnd + 2, lineEnd + 2 + size);
            at = lineEnd + 2 + size + 2;
        }
        return out.toString();
    }
}
