package robotworld.space.remote;

import java.util.concurrent.TimeUnit;

/**
 * Which of a space's servers a client talks to, and which it moves on to when that one fails: the next one in the
 * list that has not failed lately; if all have, one that answered (it could not complete a call, but it is there)
 * before one that could not be reached, and of those the one whose failure is oldest. Without the memory, a client
 * of a server that has a moment's trouble would move on to one known to be down, and on a real network a crashed
 * computer costs a whole connect timeout before the client moves on again. Not thread-safe: its owner
 * synchronizes.
 */
final class ServerRotation {

    /** How long a server that failed is passed over. */
    static final long SUSPECT_NANOS = TimeUnit.SECONDS.toNanos(10);

    private final long[] lastFailed; // System.nanoTime() of each server's last failure; 0 = never
    private final boolean[] unreachable; // whether that failure was one of reaching it (else: it answered)
    private int current;

    ServerRotation(int servers) {
        if (servers < 1) {
            throw new IllegalArgumentException("no servers");
        }
        lastFailed = new long[servers];
        unreachable = new boolean[servers];
    }

    /** The index of the server calls go to now. */
    int current() {
        return current;
    }

    /**
     * The current server failed at {@code now} ({@link System#nanoTime()}): it could not be reached (a refused or
     * broken connection, no answer in time), or it answered that it could not complete the call. Moves on, and
     * returns the index of the server calls go to next.
     */
    int failed(long now, boolean couldNotBeReached) {
        lastFailed[current] = now == 0 ? 1 : now; // 0 means "never failed"
        unreachable[current] = couldNotBeReached;
        current = next(now);
        return current;
    }

    /**
     * Whether a client that moved on from the first server may check if it can go back to it: not while that
     * server's failure is recent.
     */
    boolean mayGoHome(long now) {
        return current != 0 && (lastFailed[0] == 0 || now - lastFailed[0] > SUSPECT_NANOS);
    }

    /** The first server did not serve when checked at {@code now}: it is passed over for a while again. */
    void homeFailed(long now) {
        lastFailed[0] = now == 0 ? 1 : now;
        unreachable[0] = true;
    }

    /** Calls go to the first server again; returns its index. */
    int wentHome() {
        current = 0;
        return current;
    }

    private int next(long now) {
        int best = -1;
        for (int step = 1; step < lastFailed.length; step++) {
            int candidate = (current + step) % lastFailed.length;
            long failedAt = lastFailed[candidate];
            if (failedAt == 0 || now - failedAt > SUSPECT_NANOS) {
                return candidate;
            }
            if (best < 0 || isBetterBet(candidate, best)) {
                best = candidate;
            }
        }
        return best < 0 ? current : best;
    }

    /** Of two servers that both failed lately: one that answered, else the one whose failure is older. */
    private boolean isBetterBet(int candidate, int than) {
        if (unreachable[candidate] != unreachable[than]) {
            return !unreachable[candidate];
        }
        return lastFailed[candidate] - lastFailed[than] < 0;
    }
}
