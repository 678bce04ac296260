package robotworld.testsupport;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;

/**
 * The baseline the benchmarks measure against: a tiny TCP exchange on loopback (TCP_NODELAY both ways), with a
 * peer thread that answers every request of {@code requestBytes} with {@code replyBytes}.
 */
public final class TcpEcho implements AutoCloseable {

    private final ServerSocket server;
    private final Socket client;
    private final InputStream in;
    private final OutputStream out;
    private final byte[] request;
    private final byte[] reply;

    public TcpEcho(int requestBytes, int replyBytes) throws IOException {
        if (replyBytes > requestBytes) {
            throw new IllegalArgumentException("the peer answers with part of what it received");
        }
        request = new byte[requestBytes];
        reply = new byte[replyBytes];
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        Thread peer = new Thread(this::serve, "tcp-echo");
        peer.setDaemon(true);
        peer.start();
        client = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort());
        client.setTcpNoDelay(true);
        in = client.getInputStream();
        out = client.getOutputStream();
    }

    private void serve() {
        try (Socket socket = server.accept()) {
            socket.setTcpNoDelay(true);
            InputStream peerIn = socket.getInputStream();
            OutputStream peerOut = socket.getOutputStream();
            byte[] buffer = new byte[request.length];
            while (peerIn.readNBytes(buffer, 0, buffer.length) == buffer.length) {
                peerOut.write(buffer, 0, reply.length);
                peerOut.flush();
            }
        } catch (IOException e) {
            // the benchmark is over
        }
    }

    /** One request out and its reply back. */
    public void roundTrip() throws IOException {
        out.write(request);
        out.flush();
        if (in.readNBytes(reply, 0, reply.length) != reply.length) {
            throw new IOException("echo peer closed");
        }
    }

    @Override
    public void close() throws IOException {
        client.close();
        server.close();
    }
}
