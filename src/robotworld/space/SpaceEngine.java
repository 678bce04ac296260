package robotworld.space;

import java.util.List;
import java.util.Optional;

/**
 * The space as a server serves it: {@link Capi}, plus removals that can be undone until the client confirms them,
 * container sequence numbers, and operations that <b>wait without a thread</b>. A space server
 * ({@code robotworld.space.server.SpaceServer}) needs nothing else from the space behind it, so any engine that
 * implements this interface (the in-process {@link EmbeddedSpace}, or a clustered one) plugs into the same server
 * with the same waiting behaviour.
 *
 * <p><b>Waiting without a thread.</b> {@link #readLater}, {@link #removeLater} and {@link #writeLater} start an
 * operation that may have to wait and return at once. The outcome goes to a {@link Completion}, which is called
 * <b>exactly once</b>, unless {@link Pending#cancel()} withdrew the operation first (then never):
 * <ul>
 *   <li>if the operation can happen at once (or fails at once, e.g. {@link Timeout#TRY_ONCE} and not possible),
 *       on the calling thread, before the method returns;</li>
 *   <li>otherwise on the thread of the operation that made it possible (the write, shift, take or restore that
 *       changed the container), right after that operation, outside the container's lock; this is what lets a
 *       server answer a waiting take from the request that wrote its entry, with no thread hand-off;</li>
 *   <li>when its timeout runs out, with {@link SpaceTimeoutException}, on an engine timer thread; an
 *       {@link Timeout#INFINITE infinite} wait never times out;</li>
 *   <li>when its container is destroyed ({@link ContainerDestroyedException}) or the space closes
 *       ({@link SpaceClosedException}), on the thread that does that.</li>
 * </ul>
 * A waiting operation keeps its place among the container's waiting operations exactly as a blocking one does
 * (oldest first, the hand-over done under the container's lock), so an entry taken for it is never lost: either
 * the completion receives it, or {@code cancel()} returned true and the operation had no effect.
 *
 * <p>Completions must not block (they run on other callers' threads, timer threads or servlet threads): they hand
 * longer work to a thread of their own. They may call the engine again. A completion that throws is logged and
 * ignored; the operation's outcome stands.
 *
 * <p>Failures that are known before any waiting (no such container, selectors that can never be satisfied, a
 * closed space, null arguments) are thrown by the method itself, and the completion is not called.
 */
public interface SpaceEngine extends Capi {

    /**
     * A {@code take} (or, with {@link Operation#DESTROY}, a {@code destroy}) whose effect can be undone with
     * {@link Removal#restore()}: a server keeps it until its client confirms receipt, and restores the entries if
     * the confirmation never comes.
     *
     * @param container the container
     * @param operation {@link Operation#TAKE} or {@link Operation#DESTROY}
     * @param timeout   how long to wait for enough entries
     * @param selectors a selector chain; none means one entry in the base order
     * @return the removal, already done
     */
    Removal removeWithReceipt(ContainerRef container, Operation operation, Timeout timeout, Selector... selectors);

    /**
     * The sequence number of the latest operation on a container, as carried by {@link Notification#sequence()}.
     *
     * @param container the container
     * @return the latest sequence number (0 before the first operation)
     * @throws ContainerNotFoundException if the container does not exist
     */
    long sequence(ContainerRef container);

    /**
     * A {@code read} that waits without a thread; see the class comment for when {@code done} is called.
     *
     * @return a handle to withdraw the read
     */
    Pending readLater(ContainerRef container, Timeout timeout, Selector[] selectors, Completion<List<Entry>> done);

    /**
     * A {@link #removeWithReceipt} that waits without a thread.
     *
     * @param operation {@link Operation#TAKE} or {@link Operation#DESTROY}
     * @return a handle to withdraw the removal while it waits
     */
    Pending removeLater(ContainerRef container, Operation operation, Timeout timeout, Selector[] selectors,
                        Completion<Removal> done);

    /**
     * A {@code write} that waits (for room, a free key or position) without a thread.
     *
     * @return a handle to withdraw the write while it waits
     */
    Pending writeLater(ContainerRef container, Timeout timeout, List<Item> items, Completion<Void> done);

    /**
     * Whether this engine's calls may block their thread for a while (a clustered engine's calls cross the
     * network): a server then runs each request on a pool thread, not on the thread that read it. The in-process
     * engine's calls never block.
     *
     * @return false unless overridden
     */
    default boolean callsMayBlock() {
        return false;
    }

    /**
     * Whether {@link #spaceUri()} names this space wherever it is served (a clustered engine is served by each of
     * its members): servers then hand out crefs with it unchanged, so that a cref from one server works on all of
     * them. Otherwise a server's crefs carry its own URL.
     *
     * @return false unless overridden
     */
    default boolean sharedUri() {
        return false;
    }

    /**
     * Where servers keep what they promised the clients of this space about calls with ids (held removals, writes
     * that happened, cancelled calls), or null: each server keeps them itself, with this space. A space served by
     * several servers at once (a cluster) keeps them itself, so that any of its servers honours them.
     *
     * @return null unless overridden
     */
    default CallReceipts receipts() {
        return null;
    }

    /**
     * {@link #removeLater} for the call {@code callId} of a server's client (null: none). A space that keeps
     * receipts ({@link #receipts()}) holds the removal under that id until it is confirmed, and refuses a call that
     * was cancelled before it arrived ({@link CallCancelledException}); others ignore the id.
     *
     * @return a handle to withdraw the removal while it waits
     */
    default Pending removeLater(ContainerRef container, Operation operation, Timeout timeout, Selector[] selectors,
                                String callId, Completion<Removal> done) {
        return removeLater(container, operation, timeout, selectors, done);
    }

    /**
     * {@link #writeLater} for the call {@code callId} of a server's client (null: none); see
     * {@link #removeLater(ContainerRef, Operation, Timeout, Selector[], String, Completion)}.
     *
     * @return a handle to withdraw the write while it waits
     */
    default Pending writeLater(ContainerRef container, Timeout timeout, List<Item> items, String callId,
                               Completion<Void> done) {
        return writeLater(container, timeout, items, done);
    }

    /**
     * {@link #shift} for the call {@code callId} of a server's client (null: none); see
     * {@link #removeLater(ContainerRef, Operation, Timeout, Selector[], String, Completion)}.
     *
     * @return the displaced entries
     */
    default List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items, String callId) {
        return shift(container, timeout, items);
    }

    /**
     * The cluster this engine runs on, for operators ({@code GET <path>/health} of a space server answers it); empty
     * for an engine that lives in one process. May ask the other members and take a while: not for hot paths.
     */
    default Optional<ClusterHealth> clusterHealth() {
        return Optional.empty();
    }

    /** Where the outcome of an operation started with one of the {@code ...Later} methods goes. */
    interface Completion<T> {

        /** The operation happened; {@code result} is what it returned ({@code null} for a write). */
        void completed(T result);

        /**
         * The operation failed without effect: {@link SpaceTimeoutException}, {@link ContainerDestroyedException},
         * {@link SpaceClosedException}.
         */
        void failed(SpaceException failure);
    }

    /** An operation that may still be waiting. */
    interface Pending {

        /** A handle for an operation that completed before its method returned. */
        Pending DONE = () -> false;

        /**
         * Withdraws the operation if it still waits.
         *
         * @return true if it was withdrawn: it had no effect and its completion is never called; false if it has
         *         completed (or is completing): its completion has been or is being called with its outcome
         */
        boolean cancel();
    }
}
