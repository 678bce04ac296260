package robotworld.space.server;

import org.eclipse.jetty.http.HttpFields;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.http.MetaData;
import org.eclipse.jetty.io.Connection;
import org.eclipse.jetty.io.EndPoint;
import org.eclipse.jetty.server.AbstractConnectionFactory;
import org.eclipse.jetty.server.ConnectionFactory;
import org.eclipse.jetty.server.Connector;

import robotworld.space.wire.Frames;

/**
 * Turns an HTTP/1.1 connection into a {@link FrameConnection} when its client asks for it with the standard
 * upgrade request ({@code GET <path>} with {@code Connection: Upgrade} and {@code Upgrade: }{@value Frames#PROTOCOL},
 * answered {@code 101 Switching Protocols}), as WebSocket does. Jetty's HTTP connection finds this factory among
 * the connector's and asks it; every other connection stays HTTP and pays nothing for frames existing.
 */
final class FrameProtocol extends AbstractConnectionFactory implements ConnectionFactory.Upgrading {

    private volatile ServerState state;

    FrameProtocol() {
        super(Frames.PROTOCOL);
    }

    /** The server's state, known once the server is built (after the connector that needs this factory). */
    void serve(ServerState state) {
        this.state = state;
    }

    @Override
    public Connection upgradeConnection(Connector connector, EndPoint endPoint, MetaData.Request request,
                                        HttpFields.Mutable response) {
        ServerState served = state;
        if (served == null || !"GET".equals(request.getMethod())
                || !served.options.path().equals(request.getHttpURI().getPath())) {
            return null; // not this space's URL: the request is served as HTTP (and gets its 404)
        }
        // the 101 names what the connection switches to (RFC 9110, 7.8)
        response.put(HttpHeader.CONNECTION, "Upgrade");
        response.put(HttpHeader.UPGRADE, Frames.PROTOCOL);
        return configure(new FrameConnection(endPoint, connector.getExecutor(), served), connector, endPoint);
    }

    @Override
    public Connection newConnection(Connector connector, EndPoint endPoint) {
        throw new UnsupportedOperationException("frames start with an HTTP upgrade, never on a connection's own");
    }
}
