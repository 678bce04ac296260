package robotworld.explorer.monitor;

/**
 * The recent values of one channel: a ring of at most {@code capacity} points (time in seconds, value), so its
 * memory is fixed however long a run lasts; the oldest point makes room for a new one. Thread-safe: written by
 * the tap's thread, read by the Swing thread.
 */
public final class TimeSeries {

    private final double[] times;
    private final double[] values;
    private int start;
    private int size;
    private long added;

    /** A series of at most {@code capacity} points. */
    public TimeSeries(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity must be positive, was " + capacity);
        }
        times = new double[capacity];
        values = new double[capacity];
    }

    /** Adds a point; times should not decrease. */
    public synchronized void add(double time, double value) {
        int end = (start + size) % times.length;
        times[end] = time;
        values[end] = value;
        if (size < times.length) {
            size++;
        } else {
            start = (start + 1) % times.length;
        }
        added++;
    }

    /** The points at or after {@code from} seconds, oldest first: {@code {times, values}}. */
    public synchronized double[][] since(double from) {
        int first = 0;
        while (first < size && times[(start + first) % times.length] < from) {
            first++;
        }
        int count = size - first;
        double[][] copy = new double[2][count];
        for (int i = 0; i < count; i++) {
            int index = (start + first + i) % times.length;
            copy[0][i] = times[index];
            copy[1][i] = values[index];
        }
        return copy;
    }

    /** Points held now (at most the capacity). */
    public synchronized int size() {
        return size;
    }

    /** Points added since the series was made (grows; {@link #size()} does not). */
    public synchronized long added() {
        return added;
    }

    /** The most points it holds. */
    public int capacity() {
        return times.length;
    }

    /** The newest value, or NaN when empty. */
    public synchronized double last() {
        return size == 0 ? Double.NaN : values[(start + size - 1) % times.length];
    }
}
