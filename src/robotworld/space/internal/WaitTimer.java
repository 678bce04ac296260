package robotworld.space.internal;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * The timeouts of operations that wait without a thread: a timing wheel of 10 ms slots, ticked by one daemon thread
 * while timeouts are pending (and for a while after), so that starting and ending a wait costs a set insertion and
 * removal, never a wake-up of a timer thread. A general-purpose scheduler wakes its thread whenever a wait becomes
 * the earliest one, which, in a request/answer exchange, is nearly every wait: on a machine with few CPUs that
 * thread switch is a noticeable part of the exchange. Timeouts fire at their deadline or up to one slot later,
 * never earlier.
 */
final class WaitTimer {

    private static final long SLOT_NANOS = TimeUnit.MILLISECONDS.toNanos(10);
    private static final int SLOTS = 512;
    /** How long the thread keeps ticking with nothing to time, before it parks. */
    private static final long LINGER_NANOS = TimeUnit.SECONDS.toNanos(2);
    private static final System.Logger LOG = System.getLogger(WaitTimer.class.getName());

    private final String name;
    @SuppressWarnings("unchecked")
    private final Set<Timeout>[] wheel = new Set[SLOTS];
    private final AtomicInteger pending = new AtomicInteger();
    private final long origin = System.nanoTime();
    private volatile Thread thread;
    private volatile boolean parked;
    private volatile boolean closed;

    WaitTimer(String name) {
        this.name = name;
        for (int i = 0; i < SLOTS; i++) {
            wheel[i] = ConcurrentHashMap.newKeySet();
        }
    }

    /** A timeout that can be cancelled. */
    final class Timeout {
        private final long deadline;
        private final Runnable task;
        private final Set<Timeout> slot;

        private Timeout(long deadline, Runnable task) {
            this.deadline = deadline;
            this.task = task;
            this.slot = wheel[(int) (Math.floorMod(tickOf(deadline) + 1, (long) SLOTS))];
        }

        /** Stops the timeout if it has not fired. */
        void cancel() {
            if (slot.remove(this)) {
                pending.decrementAndGet();
            }
        }
    }

    /** Runs {@code task} on the timer thread once {@code delayNanos} have passed; null once closed. */
    Timeout schedule(Runnable task, long delayNanos) {
        if (closed) {
            return null;
        }
        Timeout timeout = new Timeout(System.nanoTime() + delayNanos, task);
        timeout.slot.add(timeout);
        pending.incrementAndGet();
        Thread ticking = thread;
        if (ticking == null) {
            start();
        } else if (parked) {
            LockSupport.unpark(ticking);
        }
        return timeout;
    }

    private synchronized void start() {
        if (thread == null && !closed) {
            Thread ticking = new Thread(this::run, name + "-timeouts");
            ticking.setDaemon(true);
            thread = ticking;
            ticking.start();
        }
    }

    void close() {
        closed = true;
        Thread ticking = thread;
        if (ticking != null) {
            LockSupport.unpark(ticking);
        }
    }

    private long tickOf(long nanos) {
        return (nanos - origin) / SLOT_NANOS;
    }

    private void run() {
        long done = tickOf(System.nanoTime()) - 1;
        long idleSince = System.nanoTime();
        while (!closed) {
            long now = System.nanoTime();
            long current = tickOf(now);
            for (long tick = Math.max(done + 1, current - SLOTS + 1); tick <= current; tick++) {
                for (Timeout timeout : wheel[(int) Math.floorMod(tick, (long) SLOTS)]) {
                    if (timeout.deadline - now <= 0 && timeout.slot.remove(timeout)) {
                        pending.decrementAndGet();
                        try {
                            timeout.task.run();
                        } catch (RuntimeException e) {
                            LOG.log(System.Logger.Level.WARNING, "a timeout failed", e);
                        }
                    }
                }
            }
            done = current;
            if (pending.get() > 0) {
                idleSince = now;
            } else if (now - idleSince > LINGER_NANOS) {
                parked = true;
                if (pending.get() == 0 && !closed) {
                    LockSupport.park(this);
                }
                parked = false;
                idleSince = System.nanoTime();
                continue;
            }
            LockSupport.parkNanos(this, origin + (current + 1) * SLOT_NANOS - System.nanoTime());
        }
    }
}
