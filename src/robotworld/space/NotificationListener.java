package robotworld.space;

/**
 * Receives the notifications of one subscription. Calls come from a delivery thread of the space, one at a
 * time and in the order the operations happened; a listener may take as long as it likes and may call the
 * space, but while it is busy its own undelivered notifications queue up (see {@link SubscriptionEnd#OVERFLOWED}).
 */
@FunctionalInterface
public interface NotificationListener {

    /** One matching operation. */
    void onNotification(Notification notification);

    /**
     * Called exactly once, after the last notification, when the subscription has ended. The default does
     * nothing.
     */
    default void onEnd(SubscriptionEnd reason) {
    }
}
