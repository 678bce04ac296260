package robotworld.sim.control;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.PortName;

/**
 * Serves a simulator's {@link ControlCommands} as a line protocol (see the package description), from a stream
 * pair such as standard input and output, or from loopback TCP connections, each on its own thread. Commands are
 * carried out one at a time, whichever connection they come from.
 */
public final class ControlChannel implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(ControlChannel.class);
    /** Longest line taken; longer ones are refused (no command needs more). */
    private static final int MAX_LINE = 1_000;
    /** How many TCP connections may be open at once. */
    private static final int MAX_CONNECTIONS = 8;

    private final ControlCommands commands;
    private final List<AutoCloseable> open = new CopyOnWriteArrayList<>();
    private ServerSocket server;
    private volatile boolean closed;

    public ControlChannel(ControlCommands commands) {
        this.commands = commands;
    }

    /**
     * Opens a channel where the command line says: {@code stdin} (standard input, answers on standard output) or
     * {@code tcp://127.0.0.1:PORT} (loopback only; 0 picks a free port).
     *
     * @return the channel and where it is, for people
     * @throws IllegalArgumentException for anything else
     */
    public static Opened open(String where, ControlCommands commands) throws IOException {
        ControlChannel channel = new ControlChannel(commands);
        if (where.equals("stdin")) {
            channel.serve(System.in, System.out, "stdin");
            return new Opened(channel, "standard input");
        }
        PortName parsed = PortName.parseListening(where);
        if (!(parsed instanceof PortName.Tcp tcp)
                || !InetAddress.getByName(tcp.host()).isLoopbackAddress()) {
            throw new IllegalArgumentException("the control channel is stdin or tcp://127.0.0.1:PORT (loopback "
                    + "only), not '" + where + "'");
        }
        return new Opened(channel, channel.listen(tcp.port()));
    }

    /**
     * A channel just opened.
     *
     * @param channel close it to stop serving
     * @param where "standard input" or the port name, e.g. {@code tcp://127.0.0.1:40123}
     */
    public record Opened(ControlChannel channel, String where) {
    }

    /**
     * Listens on 127.0.0.1:{@code port} (0 picks a free one) for connections, each speaking the line protocol.
     *
     * @return the port name, e.g. {@code tcp://127.0.0.1:40123}
     */
    public synchronized String listen(int port) throws IOException {
        server = new ServerSocket();
        server.setReuseAddress(true);
        server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        open.add(server);
        Thread acceptor = new Thread(this::accept, "sim-control-accept :" + server.getLocalPort());
        acceptor.setDaemon(true);
        acceptor.start();
        return "tcp://127.0.0.1:" + server.getLocalPort();
    }

    /** Serves the line protocol on {@code in}/{@code out} (e.g. standard input and output) on a thread of its own. */
    public void serve(InputStream in, OutputStream out, String name) {
        Thread thread = new Thread(() -> session(in, out), "sim-control " + name);
        thread.setDaemon(true);
        thread.start();
    }

    private void accept() {
        while (!closed) {
            try {
                Socket socket = server.accept();
                if (open.size() > MAX_CONNECTIONS) {
                    socket.close();
                    continue;
                }
                open.add(socket);
                Thread thread = new Thread(() -> {
                    try (socket) {
                        session(socket.getInputStream(), socket.getOutputStream());
                    } catch (IOException e) {
                        LOG.debug("control connection ended: {}", e.getMessage());
                    } finally {
                        open.remove(socket);
                    }
                }, "sim-control " + socket.getRemoteSocketAddress());
                thread.setDaemon(true);
                thread.start();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("control channel: accept failed: {}", e.getMessage());
                }
            }
        }
    }

    private void session(InputStream in, OutputStream out) {
        BufferedReader reader = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
        PrintWriter writer = new PrintWriter(out, true, StandardCharsets.UTF_8);
        try {
            String line;
            while (!closed && (line = reader.readLine()) != null) {
                String answer = answer(line);
                if (answer == null) {
                    continue;
                }
                writer.println(answer);
                if (answer.equals("ok bye")) {
                    return;
                }
            }
        } catch (IOException e) {
            LOG.debug("control session ended: {}", e.getMessage());
        }
    }

    /** The answer line to one command line; null for blank lines and comments. */
    public String answer(String line) {
        String trimmed = line.strip();
        if (trimmed.isEmpty() || trimmed.startsWith("#")) {
            return null;
        }
        if (trimmed.length() > MAX_LINE) {
            return "error line longer than " + MAX_LINE + " characters";
        }
        List<String> words = new ArrayList<>(Arrays.asList(trimmed.split("\\s+")));
        String name = words.get(0).toLowerCase(java.util.Locale.ROOT);
        words.set(0, name);
        if (name.equals("help")) {
            List<String> lines = new ArrayList<>(commands.help());
            lines.add("help                     this list");
            lines.add("quit                     end this connection");
            return "ok " + String.join(" | ", lines);
        }
        if (name.equals("quit")) {
            return "ok bye";
        }
        synchronized (this) {
            try {
                String done = commands.execute(words);
                return done.isEmpty() ? "ok" : "ok " + done;
            } catch (IllegalArgumentException | IllegalStateException e) {
                return "error " + e.getMessage();
            } catch (RuntimeException e) {
                LOG.warn("control command '{}' failed", trimmed, e);
                return "error " + e;
            }
        }
    }

    @Override
    public void close() {
        closed = true;
        for (AutoCloseable closeable : open) {
            try {
                closeable.close();
            } catch (Exception e) {
                // closing anyway
            }
        }
    }
}
