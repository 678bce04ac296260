package robotworld.space.server;

import java.io.IOException;
import java.nio.channels.SelectableChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.Iterator;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;

import org.eclipse.jetty.io.EndPoint;
import org.eclipse.jetty.io.ManagedSelector;
import org.eclipse.jetty.io.SelectableChannelEndPoint;
import org.eclipse.jetty.io.SelectorManager;
import org.eclipse.jetty.io.SocketChannelEndPoint;
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
 * Each selector also gets its {@link AnswerRound}, which its connections' end points carry ({@link RoundEndPoint}).
 */
final class ClosingConnector extends ServerConnector {

    /** Accepted and not yet closed by Jetty; added by the accepting selector before the connection is served. */
    private final Set<SelectableChannel> accepted = ConcurrentHashMap.newKeySet();
    /** The listening socket: without acceptor threads, Jetty's close() leaves it to the selectors. */
    private volatile ServerSocketChannel listening;

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
            protected ManagedSelector newSelector(int id) {
                return new RoundSelector(this, id);
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

    @Override
    protected SocketChannelEndPoint newEndPoint(SocketChannel channel, ManagedSelector selector, SelectionKey key) {
        AnswerRound round = selector instanceof RoundSelector withRound ? withRound.round : null;
        RoundEndPoint endPoint = new RoundEndPoint(channel, selector, key, getScheduler(), round);
        endPoint.setIdleTimeout(getIdleTimeout());
        return endPoint;
    }

    /** A selector with its answer round, which it tells how many connections each {@code select()} found ready. */
    static final class RoundSelector extends ManagedSelector {
        final AnswerRound round;

        RoundSelector(SelectorManager manager, int id) {
            super(manager, id);
            round = new AnswerRound(this);
        }

        @Override
        protected int select(Selector selector) throws IOException {
            int ready = super.select(selector);
            round.selected(ready);
            return ready;
        }
    }

    /** A connection's end point, with the answer round of the selector that serves it. */
    static final class RoundEndPoint extends SocketChannelEndPoint {
        final AnswerRound round;

        RoundEndPoint(SocketChannel channel, ManagedSelector selector, SelectionKey key, Scheduler scheduler,
                      AnswerRound round) {
            super(channel, selector, key, scheduler);
            this.round = round;
        }
    }

    @Override
    public void open() throws IOException {
        super.open();
        listening = (ServerSocketChannel) getTransport();
    }

    /**
     * Stops listening: new connections are refused from here on, so clients move on to another server while this
     * one finishes its work. Jetty's own close() leaves the socket to the selectors when there are no acceptor
     * threads, and they do not close it if accepting was paused at the connection limit.
     */
    @Override
    public void close() {
        super.close();
        closeQuietly(listening);
    }

    /** After the server stopped: closes the listening socket and every connection Jetty left open. */
    void closeLeftOpen() {
        closeQuietly(listening);
        for (Iterator<SelectableChannel> it = accepted.iterator(); it.hasNext(); ) {
            closeQuietly(it.next());
            it.remove();
        }
    }

    private static void closeQuietly(java.nio.channels.Channel channel) {
        if (channel == null) {
            return;
        }
        try {
            channel.close();
        } catch (IOException e) {
            // closing is all we wanted
        }
    }
}
