package robotworld.sim;

import java.time.Duration;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.function.Predicate;

/**
 * The serial traffic of a simulated interface, in order, for assertions and for watching a session. Keeps the
 * latest {@value #CAPACITY} records, so a simulator that runs for days does not fill the memory.
 */
public final class WireLog {

    /** How many records are kept; older ones are dropped. */
    public static final int CAPACITY = 100_000;

    private final Deque<WireRecord> records = new ArrayDeque<>();

    synchronized void host(byte[] bytes) {
        add(new WireRecord(true, bytes.clone(), "", System.nanoTime()));
    }

    synchronized void hostIgnored(byte[] bytes, String why) {
        add(new WireRecord(true, bytes.clone(), why, System.nanoTime()));
    }

    /** Something the interface decided without sending a byte, e.g. to give up waiting for the host. */
    synchronized void deviceNote(String note) {
        add(new WireRecord(false, new byte[0], note, System.nanoTime()));
    }

    synchronized void device(byte[] bytes) {
        add(new WireRecord(false, bytes.clone(), "", System.nanoTime()));
    }

    private void add(WireRecord record) {
        if (records.size() == CAPACITY) {
            records.removeFirst();
        }
        records.addLast(record);
        notifyAll();
    }

    /** All records so far. */
    public synchronized List<WireRecord> records() {
        return List.copyOf(records);
    }

    /** All records as text, e.g. {@code ["host 04 62", "cm11a 66", "host 00", "cm11a 55"]}. */
    public synchronized List<String> lines() {
        return records.stream().map(WireRecord::toString).toList();
    }

    /** Forgets the records so far. */
    public synchronized void clear() {
        records.clear();
    }

    /**
     * Waits until the lines satisfy {@code condition}, at most {@code timeout}.
     *
     * @return whether they did
     */
    public synchronized boolean await(Predicate<List<String>> condition, Duration timeout)
            throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (!condition.test(lines())) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                return false;
            }
            wait(Math.max(1, left / 1_000_000));
        }
        return true;
    }
}
