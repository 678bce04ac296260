package robotworld.sim;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Accepts TCP connections on 127.0.0.1 only and hands each to a handler on its own thread. Like a serial port,
 * a simulator serves one host at a time; the handler decides what to do with a second one.
 */
final class LoopbackServer {

    private static final Logger LOG = LoggerFactory.getLogger(LoopbackServer.class);

    private final ServerSocket server;
    private final Thread acceptor;

    LoopbackServer(int port, String name, Consumer<Socket> handler) throws IOException {
        server = new ServerSocket();
        server.setReuseAddress(true);
        server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        acceptor = new Thread(() -> acceptLoop(handler), name + " accept :" + server.getLocalPort());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    private void acceptLoop(Consumer<Socket> handler) {
        while (!server.isClosed()) {
            try {
                handler.accept(server.accept());
            } catch (IOException e) {
                if (!server.isClosed()) {
                    LOG.warn("accept failed: {}", e.getMessage());
                }
            }
        }
    }

    /** The bound port. */
    int port() {
        return server.getLocalPort();
    }

    void close() {
        try {
            server.close();
        } catch (IOException e) {
            // closing anyway
        }
    }
}
