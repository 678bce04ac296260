package robotworld.observe;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import robotworld.space.Capi;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/**
 * Says that a space replays a recording rather than carrying a live world: every view of a world (monitor
 * windows, console monitor, Foxglove endpoint, world view) looks for it when it starts watching and marks what it
 * shows as a replay. The replayer writes it into the container {@value #CONTAINER} (a name no participant or
 * module can have) before the first replayed event, as {@code <"rwe.replay", 1, recording, recordedAtMillis,
 * rateMillionths>}.
 *
 * @param recording  the recording's file name
 * @param recordedAt when the recording started
 * @param rate       the replay speed, 1 = as recorded
 */
public record ReplayMark(String recording, Instant recordedAt, double rate) {

    /** The container holding the mark. */
    public static final String CONTAINER = "rwe.replay";
    private static final String TAG = "rwe.replay";
    private static final DateTimeFormatter WHEN = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss", Locale.ROOT)
            .withZone(ZoneId.systemDefault());

    /** Checks the fields. */
    public ReplayMark {
        Objects.requireNonNull(recording, "recording");
        Objects.requireNonNull(recordedAt, "recordedAt");
        if (!(rate > 0)) {
            throw new IllegalArgumentException("the replay rate must be positive, was " + rate);
        }
    }

    /** The container's spec: FIFO, one entry. */
    public static ContainerSpec containerSpec() {
        return ContainerSpec.of(Order.FIFO).bounded(1).named(CONTAINER);
    }

    /** The mark as a tuple. */
    public Tuple toTuple() {
        return Tuple.of(TAG, 1L, recording, recordedAt.toEpochMilli(), Math.round(rate * 1_000_000));
    }

    /** Puts the mark into {@code space} (the replayer does this first). */
    public void publish(Capi space) {
        space.shift(space.lookupOrCreateContainer(containerSpec()), Timeout.TRY_ONCE, toTuple());
    }

    /**
     * The mark of {@code space}, if it replays a recording. Creates nothing.
     *
     * @throws robotworld.space.SpaceException when the space cannot be reached
     */
    public static Optional<ReplayMark> find(Capi space) {
        List<Entry> entries;
        try {
            entries = space.read(space.lookupContainer(CONTAINER), Timeout.TRY_ONCE, Selector.fifo(1));
        } catch (ContainerNotFoundException e) {
            return Optional.empty();
        } catch (robotworld.space.SpaceTimeoutException e) {
            return Optional.empty(); // the container exists but is empty
        }
        for (Entry entry : entries) {
            if (entry instanceof Tuple t && t.arity() == 5 && t.get(0).equals(Entry.of(TAG))) {
                try {
                    return Optional.of(new ReplayMark(t.stringAt(2), Instant.ofEpochMilli(t.longAt(3)),
                            t.longAt(4) / 1e6));
                } catch (RuntimeException e) {
                    return Optional.empty();
                }
            }
        }
        return Optional.empty();
    }

    /** How views say it: {@code REPLAY of run.mcap (recorded 2026-11-23 14:02:11, 2x)}. */
    public String label() {
        String speed = rate == Math.rint(rate) ? String.valueOf((long) rate) : String.valueOf(rate);
        return "REPLAY of " + recording + " (recorded " + WHEN.format(recordedAt) + ", " + speed + "x)";
    }
}
