package robotworld.space.server;

import java.io.ByteArrayOutputStream;

import robotworld.space.ContainerRef;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.wire.Wire;
import robotworld.space.wire.WireContext;
import robotworld.space.wire.WireWriter;

/**
 * The server side of one remote subscription: a listener on the space that turns each notification into a frame
 * of its client's stream, in order. It never blocks the space: when the session's queue is full, the
 * subscription ends as {@link SubscriptionEnd#OVERFLOWED} after the notifications queued so far.
 */
final class Forwarder implements NotificationListener {

    final String id;
    final ContainerRef container;
    private final EventSession session;
    private final WireContext wire;
    private Subscription subscription;
    private boolean cancelWhenKnown;
    private volatile boolean overflowed;

    Forwarder(String id, ContainerRef container, EventSession session, WireContext wire) {
        this.id = id;
        this.container = container;
        this.session = session;
        this.wire = wire;
    }

    /** Called once the space has handed out the subscription. */
    synchronized void started(Subscription handle) {
        subscription = handle;
        if (cancelWhenKnown) {
            handle.cancel();
        }
    }

    /** Stops the subscription; the space delivers what happened before, then the end. */
    synchronized void cancel() {
        if (subscription == null) {
            cancelWhenKnown = true;
        } else {
            subscription.cancel();
        }
    }

    @Override
    public void onNotification(Notification notification) {
        if (overflowed) {
            return;
        }
        if (!session.offerNotification(notificationFrame(notification))) {
            overflowed = true;
            cancel();
        }
    }

    @Override
    public void onEnd(SubscriptionEnd reason) {
        session.ended(this, endFrame(overflowed ? SubscriptionEnd.OVERFLOWED : reason));
    }

    private byte[] notificationFrame(Notification notification) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(128);
        try (WireWriter out = wire.writer(bytes)) {
            out.startObject()
                    .field("sub", id)
                    .field("op", Wire.name(notification.operation()))
                    .field("seq", notification.sequence())
                    .entries("entries", notification.entries());
            if (!notification.displaced().isEmpty()) {
                out.entries("displaced", notification.displaced());
            }
            out.endObject();
        }
        return tail(bytes);
    }

    private byte[] endFrame(SubscriptionEnd reason) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(48);
        try (WireWriter out = wire.writer(bytes)) {
            out.startObject().field("sub", id).field("end", Wire.name(reason)).endObject();
        }
        return tail(bytes);
    }

    /** The frame without its opening brace (the session puts the frame number in front) and with a newline. */
    private static byte[] tail(ByteArrayOutputStream bytes) {
        bytes.write('\n');
        byte[] all = bytes.toByteArray();
        return java.util.Arrays.copyOfRange(all, 1, all.length);
    }
}
