package robotworld.testsupport;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * An HTTP/1.1 reverse proxy on loopback that, like many proxies, does not pass protocol upgrades: it drops the
 * {@code Upgrade} header of every request and its {@code Connection: Upgrade}, so the server answers such a request
 * as the plain request it then is. Everything else (bodies by {@code Content-Length}, the answers) passes unchanged.
 * A request that does not end its head (bytes that are not HTTP) is held back, as such a proxy waits for the rest.
 */
public final class UpgradeStrippingProxy implements AutoCloseable {

    private final ServerSocket server;
    private final int targetPort;
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();
    private volatile int upgradesStripped;

    public UpgradeStrippingProxy(int targetPort) throws IOException {
        this.targetPort = targetPort;
        server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        Thread acceptor = new Thread(this::accept, "upgrade-stripping-proxy");
        acceptor.setDaemon(true);
        acceptor.start();
    }

    public int port() {
        return server.getLocalPort();
    }

    /** How many requests asked for an upgrade that the server never saw. */
    public int upgradesStripped() {
        return upgradesStripped;
    }

    private void accept() {
        while (!server.isClosed()) {
            try {
                Socket client = server.accept();
                Socket upstream = new Socket(InetAddress.getLoopbackAddress(), targetPort);
                sockets.add(client);
                sockets.add(upstream);
                start("proxy requests", () -> relayRequests(client, upstream));
                start("proxy answers", () -> relayRaw(upstream, client));
            } catch (IOException e) {
                return; // closed
            }
        }
    }

    private static void start(String name, Runnable work) {
        Thread thread = new Thread(work, name);
        thread.setDaemon(true);
        thread.start();
    }

    private void relayRequests(Socket from, Socket to) {
        try (from; to) {
            InputStream in = from.getInputStream();
            OutputStream out = to.getOutputStream();
            while (true) {
                String head = readHead(in);
                if (head == null) {
                    return;
                }
                StringBuilder kept = new StringBuilder();
                long contentLength = 0;
                for (String line : head.split("\r\n")) {
                    String lower = line.toLowerCase(Locale.ROOT);
                    if (lower.startsWith("upgrade:")) {
                        upgradesStripped++;
                        continue;
                    }
                    if (lower.startsWith("connection:") && lower.contains("upgrade")) {
                        continue;
                    }
                    if (lower.startsWith("content-length:")) {
                        contentLength = Long.parseLong(line.substring(line.indexOf(':') + 1).trim());
                    }
                    kept.append(line).append("\r\n");
                }
                kept.append("\r\n");
                out.write(kept.toString().getBytes(StandardCharsets.ISO_8859_1));
                out.write(in.readNBytes((int) contentLength));
                out.flush();
            }
        } catch (IOException e) {
            // either side closed
        }
    }

    /** The head of the next request, without its final empty line; null at the end of the stream. */
    private static String readHead(InputStream in) throws IOException {
        ByteArrayOutputStream head = new ByteArrayOutputStream();
        int matched = 0;
        int b;
        while ((b = in.read()) >= 0) {
            head.write(b);
            matched = (b == (matched % 2 == 0 ? '\r' : '\n')) ? matched + 1 : (b == '\r' ? 1 : 0);
            if (matched == 4) {
                String text = head.toString(StandardCharsets.ISO_8859_1);
                return text.substring(0, text.length() - 4);
            }
        }
        return null;
    }

    private static void relayRaw(Socket from, Socket to) {
        try (from; to) {
            from.getInputStream().transferTo(to.getOutputStream());
        } catch (IOException e) {
            // either side closed
        }
    }

    @Override
    public void close() throws IOException {
        server.close();
        for (Socket socket : sockets) {
            socket.close();
        }
    }
}
