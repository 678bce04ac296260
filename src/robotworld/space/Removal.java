package robotworld.space;

import java.util.List;

/**
 * The result of a take or destroy that can still be undone: what a server hands out while it waits for the
 * client to confirm that the entries arrived (see {@link EmbeddedSpace#removeWithReceipt}).
 *
 * <p>The removal has fully happened (the entries are gone, their room, keys and positions are free, waiters were
 * served, observers were told). {@link #restore()} puts the entries back where they were in the container's orders,
 * under their keys and at their positions, announced to observers as a {@link Operation#WRITE}. If they cannot all
 * go back at once (the container filled up, a key or position or, for a SET, an equal entry is in the way), the
 * restoration waits at the head of the container's blocked operations, like a write that nobody can time out, so
 * the entries are never lost while the container exists.
 */
public interface Removal {

    /** The entries removed, in the order the operation returned them. */
    List<Entry> entries();

    /** Puts the entries back; idempotent, and a no-op once the container is gone. */
    void restore();
}
