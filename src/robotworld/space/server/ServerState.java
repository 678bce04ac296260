package robotworld.space.server;

import java.net.InetAddress;
import java.net.URI;
import java.util.concurrent.Semaphore;

import robotworld.space.CallReceipts;
import robotworld.space.SpaceEngine;
import robotworld.space.wire.WireContext;

/** What the servlet and the server share: the space, the wire context, the options and the call bookkeeping. */
final class ServerState {

    final SpaceEngine space;
    /** The URL clients use. */
    final URI publicUri;
    /** The URI crefs carry on the wire: the public URL, or the space's own URI when it is the same on every server. */
    final URI crefUri;
    final WireContext wire;
    final SpaceServer.Options options;
    final BearerToken token;
    /** Held removals, completed writes, cancelled calls: kept by the space itself if it can, else with it here. */
    final CallReceipts receipts;
    final CallRegistry calls;
    final SessionRegistry sessions;
    /** Bounds the calls that wait inside the space at once (each holds a small object, not a thread). */
    private final Semaphore waitingPermits;
    /** Per-client limits: connections and waiting operations per address, the request deadline. */
    final ClientLimits clients;
    volatile boolean stopping;

    ServerState(SpaceEngine space, URI publicUri, WireContext wire, SpaceServer.Options options,
                ClientLimits clients) {
        this.space = space;
        this.publicUri = publicUri;
        this.crefUri = space.sharedUri() ? space.spaceUri() : publicUri;
        this.wire = wire;
        this.options = options;
        this.token = options.token() == null ? null : new BearerToken(options.token());
        this.receipts = space.receipts() != null ? space.receipts() : SpaceReceipts.of(space);
        this.calls = new CallRegistry(receipts);
        this.sessions = new SessionRegistry(options.maxSessions(), options.sessionQueue());
        this.waitingPermits = new Semaphore(options.maxWaitingCalls());
        this.clients = clients;
    }

    /**
     * Takes a place for an operation that waits in the space: one of the server's, and one of its client's address
     * unless {@code client} is null (a request with the token).
     *
     * @return null if it got one, else why not (for the {@code busy} answer)
     */
    String enterWaiting(InetAddress client) {
        if (!waitingPermits.tryAcquire()) {
            return "too many operations are waiting on this server; try again";
        }
        if (!clients.enterWaiting(client)) {
            waitingPermits.release();
            return clients.waitingRefusal(client);
        }
        return null;
    }

    /** Gives back a place taken with {@link #enterWaiting}. */
    void leaveWaiting(InetAddress client) {
        clients.leaveWaiting(client);
        waitingPermits.release();
    }
}
