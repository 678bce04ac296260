package robotworld.space;

import java.util.List;

/**
 * A space connection that can wait for entries without a thread of its own: what a program that serves many
 * containers (a provider with many modules) uses, so that its thread count does not grow with the number of
 * containers it waits on. {@link EmbeddedSpace} and the remote client implement it.
 *
 * <p>The completion is called exactly once, unless {@link SpaceEngine.Pending#cancel()} returned true first: with
 * the taken entries, or with the failure the blocking operation would have thrown ({@link SpaceTimeoutException},
 * {@link ContainerNotFoundException}, {@link SpaceClosedException}; remotely also
 * {@link SpaceUnavailableException}). It runs on a thread of the space (the one that wrote the entry, a timer, or a
 * remote client's I/O thread) and must not block: hand longer work, such as a hardware call, to a thread of your
 * own. {@code cancel()} may block briefly (a remote client tells the server) and withdraws the take: whatever it
 * may have removed goes back.
 */
public interface AsyncTakes {

    /**
     * {@code space} itself if it can wait without a thread, else an adapter whose takes each wait on a thread of
     * their own (for wrappers and other implementations of {@link Capi}).
     */
    static AsyncTakes of(Capi space) {
        return space instanceof AsyncTakes async ? async : new ThreadPerTake(space);
    }

    /**
     * A {@code take} that waits without a thread.
     *
     * @return a handle to withdraw it
     */
    SpaceEngine.Pending takeLater(ContainerRef container, Timeout timeout, Selector[] selectors,
                                  SpaceEngine.Completion<List<Entry>> done);

    /**
     * {@link Capi#shiftThenTake} whose take waits without a thread. The shift happens first (and is not undone by a
     * cancel); a failure may leave it unknown whether the shift happened (remotely, a broken connection), in which
     * case shifting again must be harmless to the caller.
     *
     * @return a handle to withdraw the take
     */
    SpaceEngine.Pending shiftThenTakeLater(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom,
                                           Timeout timeout, Selector[] selectors,
                                           SpaceEngine.Completion<List<Entry>> done);
}
