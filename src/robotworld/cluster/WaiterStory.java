package robotworld.cluster;

import java.lang.System.Logger.Level;
import java.util.concurrent.TimeUnit;

/**
 * The steps of one waiting operation with their times, kept only while DEBUG logging of this package is on, and
 * logged when the operation ends if it had trouble: a look that failed because the cluster was recovering, a queue
 * that had to be repeated, or an end long after its last wake-up. What a member's log shows of the waits that a
 * member's loss held up; at any other level a waiter keeps {@link #NONE}, which records nothing.
 */
class WaiterStory {

    private static final System.Logger LOG = System.getLogger(WaiterStory.class.getName());

    /** Records nothing: what every waiter keeps unless DEBUG is on. */
    static final WaiterStory NONE = new WaiterStory();

    /** A story for a new waiter: a recording one at DEBUG, {@link #NONE} otherwise. */
    static WaiterStory begin() {
        return LOG.isLoggable(Level.DEBUG) ? new Recording() : NONE;
    }

    /** A step of the waiter, with a detail (may be null). */
    void note(String step, Object detail) {
    }

    /** A step of the waiter, with a number. */
    void note(String step, long number) {
    }

    /** A step that shows the cluster in trouble: the story is logged when the waiter ends. */
    void trouble(String step, Object detail) {
    }

    /** The waiter was woken (a step follows). */
    void woken() {
    }

    /** The waiter ended; logs the story if it had trouble. */
    void ended(Object what, Object outcome) {
    }

    private static final class Recording extends WaiterStory {
        private final long born = System.nanoTime();
        private final StringBuilder steps = new StringBuilder();
        private long lastWoken;
        private boolean troubled;

        @Override
        synchronized void note(String step, Object detail) {
            steps.append(" +").append(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - born)).append(" ms ")
                    .append(step);
            if (detail != null) {
                steps.append(' ').append(detail);
            }
            steps.append(';');
        }

        @Override
        void note(String step, long number) {
            note(step, (Object) number);
        }

        @Override
        synchronized void trouble(String step, Object detail) {
            troubled = true;
            note(step, detail);
        }

        @Override
        synchronized void woken() {
            lastWoken = System.nanoTime();
            note("woken", null);
        }

        @Override
        synchronized void ended(Object what, Object outcome) {
            long now = System.nanoTime();
            boolean slowAfterWakeUp = lastWoken != 0
                    && TimeUnit.NANOSECONDS.toMillis(now - lastWoken) > ClusterNode.SLOW_CALL_MILLIS;
            if (troubled || slowAfterWakeUp) {
                LOG.log(Level.DEBUG, "waiting operation on " + what + " ended after "
                        + TimeUnit.NANOSECONDS.toMillis(now - born) + " ms with " + outcome + ":" + steps);
            }
        }
    }
}
