package robotworld.sim.robot;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Function;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.PortName;
import robotworld.bus.SerialLink;
import robotworld.bus.TcpSerialLink;

/**
 * Serves the simulated bus as a raw serial-over-TCP endpoint (what ser2net offers for a real bus): every
 * accepted connection is a line to the bus. Several connections may be open; their requests share the modules.
 */
final class RobotBusServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(RobotBusServer.class);

    private final ServerSocket server;
    private final Function<SerialLink, RtuServerSession> sessions;
    private final List<RtuServerSession> open = new CopyOnWriteArrayList<>();
    private final String host;

    RobotBusServer(String host, int port, Function<SerialLink, RtuServerSession> sessions) throws IOException {
        this.sessions = sessions;
        this.host = host;
        server = new ServerSocket();
        server.setReuseAddress(true);
        try {
            server.bind(new InetSocketAddress(host, port));
        } catch (IOException e) {
            server.close();
            throw new IOException("cannot listen on " + new PortName.Tcp(host, port).text() + ": " + e.getMessage(), e);
        }
        Thread acceptor = new Thread(this::acceptLoop, "robot-sim-accept :" + server.getLocalPort());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    /** The port name clients use, e.g. {@code tcp://127.0.0.1:40123}. */
    String portName() {
        return new PortName.Tcp(host, server.getLocalPort()).text();
    }

    private void acceptLoop() {
        while (!server.isClosed()) {
            try {
                Socket socket = server.accept();
                RtuServerSession session = sessions.apply(new TcpSerialLink(socket));
                open.add(session);
                Thread thread = new Thread(() -> {
                    try {
                        session.run();
                    } finally {
                        open.remove(session);
                    }
                }, "robot-sim-session " + socket.getRemoteSocketAddress());
                thread.setDaemon(true);
                thread.start();
            } catch (IOException e) {
                if (!server.isClosed()) {
                    LOG.warn("accept failed: {}", e.getMessage());
                }
            }
        }
    }

    @Override
    public void close() {
        try {
            server.close();
        } catch (IOException e) {
            // closing anyway
        }
        for (RtuServerSession session : open) {
            session.close();
        }
    }
}
