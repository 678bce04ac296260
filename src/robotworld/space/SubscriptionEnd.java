package robotworld.space;

/** Why a subscription ended; passed to {@link NotificationListener#onEnd}. */
public enum SubscriptionEnd {
    /** {@link Subscription#cancel()} was called. */
    CANCELLED,
    /** A {@link NotificationMode#ONCE} subscription fired. */
    FIRED_ONCE,
    /** Its timeout passed (see {@link NotificationMode}). */
    EXPIRED,
    /** The container was destroyed. */
    CONTAINER_DESTROYED,
    /**
     * The listener fell too far behind: its queue of undelivered notifications was full when another operation
     * matched. Every notification before that operation was delivered; that one and all later ones were not.
     * Subscribe again (and re-read the container) to resume.
     */
    OVERFLOWED,
    /** The space was closed. */
    SPACE_CLOSED
}
