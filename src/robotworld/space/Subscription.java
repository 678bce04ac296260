package robotworld.space;

/** A handle on an active notification subscription. */
public interface Subscription {

    /** The container observed. */
    ContainerRef container();

    /** Whether notifications are still being produced for it. */
    boolean isActive();

    /**
     * Stops the subscription. Operations that happened before the call are still delivered, then the listener
     * gets {@link SubscriptionEnd#CANCELLED}. Cancelling an ended subscription does nothing.
     */
    void cancel();
}
