package robotworld.space.server;

import java.io.IOException;
import java.nio.channels.SelectableChannel;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;

import org.eclipse.jetty.io.EndPoint;
import org.eclipse.jetty.io.SelectableChannelEndPoint;
import org.eclipse.jetty.io.SelectorManager;
import org.eclipse.jetty.server.ConnectionFactory;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.util.thread.Scheduler;

/**
 * Jetty's {@link ServerConnector}, made to close every connection it accepted when the server stops. A connection
 * left open by a stopped server answers nothing: its client waits out its whole deadline on a server that is gone,
 * while a server started in its place could answer at once. A crashed process's connections close; a stopped
 * server's must too. Two ways that happened:
 * <ul>
 *   <li>A blocking accept interrupted by the stop just as it took a connection throws, and the JDK never closes
 *   the socket it accepted. So connections are accepted by the selector threads, without blocking (no acceptor
 *   threads), which the stop does not interrupt.</li>
 *   <li>A connection accepted while the selectors stop may never be served or closed. So every accepted connection
 *   is tracked until Jetty closes it, and {@link #closeLeftOpen()} closes the rest once the server has stopped.</li>
 * </ul>
 */
final class ClosingConnector extends ServerConnector {

    /** Accepted and not yet closed by Jetty; filled from the acceptor thread before the selector sees them. */
    private final Set<SelectableChannel> accepted = ConcurrentHashMap.newKeySet();

    ClosingConnector(Server server, Executor executor, int selectors, ConnectionFactory... factories) {
        super(server, executor, null, null, 0, selectors, factories); // 0 acceptors: the selectors accept
    }

    @Override
    protected SelectorManager newSelectorManager(Executor executor, Scheduler scheduler, int selectors) {
        // called from the super constructor: the overrides read the field only once connections come
        return new ServerConnectorManager(executor, scheduler, selectors) {
            @Override
            protected void onAccepting(SelectableChannel channel) {
                accepted.add(channel);
                super.onAccepting(channel);
            }

            @Override
            protected void onAcceptFailed(SelectableChannel channel, Throwable cause) {
                accepted.remove(channel);
                super.onAcceptFailed(channel, cause);
            }

            @Override
            protected void endPointClosed(EndPoint endPoint) {
                if (endPoint instanceof SelectableChannelEndPoint channelEndPoint) {
                    accepted.remove(channelEndPoint.getChannel());
                }
                super.endPointClosed(endPoint);
            }
        };
    }

    /** After the server stopped: closes every connection Jetty left open. */
    void closeLeftOpen() {
        for (SelectableChannel channel : accepted) {
            try {
                channel.close();
            } catch (IOException e) {
                // closing is all we wanted
            }
        }
        accepted.clear();
    }
}
