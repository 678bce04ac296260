package robotworld.space;

import java.util.List;

/**
 * What a space's servers promise their clients about calls with ids: removals held until their client confirms
 * receipt, writes and shifts that happened, and calls cancelled before they arrived. A server keeps them itself,
 * with the space it serves, unless the space keeps them ({@link SpaceEngine#receipts()}): a clustered space keeps
 * them in its containers, so that a client whose server failed can settle its calls with another member's server.
 */
public interface CallReceipts {

    /** Holds a removal until {@code callId} is acknowledged; its entries come back after {@code leaseMillis}. */
    void hold(String callId, Removal removal, long leaseMillis);

    /**
     * The client says call {@code callId}, which it is about to acknowledge or cancel, ran on container
     * {@code containerId}. A space that keeps receipts in its containers settles the call there instead of asking
     * every container; a wrong hint can only spoil that client's own call. Others ignore it.
     */
    default void hint(String callId, String containerId) {
    }

    /** The client received the answer of {@code callId}: its removal stands. */
    void acknowledge(String callId);

    /**
     * The client received the answers of {@code callIds}; done (for good) when this returns, since the client is
     * then told so and will not send them again.
     */
    default void acknowledge(List<String> callIds) {
        callIds.forEach(this::acknowledge);
    }

    /** Undoes the held removal of {@code callId}; whether there was one. */
    boolean restore(String callId);

    /** The write (no displaced entries) or shift of {@code callId} happened. */
    void completed(String callId, List<Entry> displaced);

    /** What the write or shift of {@code callId} displaced if it happened (recently), else null; forgets it. */
    List<Entry> takeCompleted(String callId);

    /**
     * Makes sure call {@code callId}, which is not running on this server, never takes effect when it arrives.
     *
     * @return what it displaced if it turned out to have happened meanwhile (a write or shift), else null
     */
    List<Entry> forbid(String callId);

    /** Whether {@code callId} was cancelled before it arrived; forgets the cancel. */
    boolean isForbidden(String callId);

    /** Removals held for confirmation right now (for monitoring and tests). */
    int held();
}
