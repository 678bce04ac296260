package robotworld.space;

/**
 * How long a subscription lasts, together with its timeout (see {@link Capi#subscribe}).
 */
public enum NotificationMode {
    /** Ends after it has fired once, or when the timeout passes without it having fired. */
    ONCE,
    /** Fires every time; each firing restarts the timeout, so it ends after a full timeout without an event. */
    PROLONG,
    /** Fires every time until the timeout, counted from the subscription, has passed. */
    RESTRICTED,
    /** Fires every time until cancelled; the timeout is ignored. */
    INFINITE
}
