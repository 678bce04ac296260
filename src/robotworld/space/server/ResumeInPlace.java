package robotworld.space.server;

import org.eclipse.jetty.server.internal.HttpConnection;
import org.eclipse.jetty.util.thread.TryExecutor;

/**
 * The connector's executor: Jetty's thread pool, except that a connection going back to reading after an
 * operation's answer sent from another thread reads on that thread instead of waking a pool thread for it.
 *
 * <p>Why: a waiting operation's answer is sent by the thread that completes it (the one that handled the matching
 * write, or the space's timer), after the request's own handling has returned. Jetty then resumes the answered
 * connection by handing it to a pool thread, which mostly finds nothing to read yet and registers for reading
 * again: a thread wake-up per answered wait (two per module call) and, in a burst of a thousand answers, a burst
 * of pool threads. Reading here instead costs one non-blocking read. Everything such a read can start is
 * non-blocking (operations never block, other requests are handed to the pool by {@link OperationsHandler}).
 * Only the answers of operations ({@link #answering}) resume in place; the servlet's requests complete as Jetty
 * does it. Nesting is bounded so that a chain of answers cannot grow the stack.
 */
final class ResumeInPlace implements TryExecutor {

    private static final int MAX_NESTING = 2;
    /** Per thread: {operation answers being sent, connections resumed in place}. */
    private static final ThreadLocal<int[]> STATE = ThreadLocal.withInitial(() -> new int[2]);

    private final TryExecutor pool;

    ResumeInPlace(TryExecutor pool) {
        this.pool = pool;
    }

    /** Sends an operation's answer with {@code send}; a connection it lets read on may do so on this thread. */
    static void answering(Runnable send) {
        int[] state = STATE.get();
        state[0]++;
        try {
            send.run();
        } finally {
            state[0]--;
        }
    }

    @Override
    public void execute(Runnable task) {
        if (task instanceof HttpConnection) {
            int[] state = STATE.get();
            if (state[0] > 0 && state[1] < MAX_NESTING) {
                state[1]++;
                try {
                    task.run();
                } finally {
                    state[1]--;
                }
                return;
            }
        }
        pool.execute(task);
    }

    @Override
    public boolean tryExecute(Runnable task) {
        return pool.tryExecute(task);
    }
}
