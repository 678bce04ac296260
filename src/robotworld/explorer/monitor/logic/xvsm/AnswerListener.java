package robotworld.explorer.monitor.logic.xvsm;

import java.time.Instant;
import robotworld.xvsm.CallTuple;

/** Hears the answers a module publishes; called on a delivery thread of the space, one at a time. */
public interface AnswerListener {

    /** An answer (or error answer) arrived in the module's ANSWER container at {@code when}. */
    void answer(CallTuple answer, Instant when);

    /**
     * An answer that was already in the module's ANSWER container when watching started; when it was written is
     * not known. Handed over before any {@link #answer}, oldest first. Default: nothing.
     */
    default void earlier(CallTuple answer) {
    }

    /** Watching ended for good (the space closed or the subscription could not be renewed). Default: nothing. */
    default void stopped(String why) {
    }
}
