package robotworld.space.server;

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
    final Semaphore waitingPermits;
    volatile boolean stopping;

    ServerState(SpaceEngine space, URI publicUri, WireContext wire, SpaceServer.Options options) {
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
    }
}
