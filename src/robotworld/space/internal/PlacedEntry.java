package robotworld.space.internal;

import java.util.Objects;

import robotworld.space.Entry;

/**
 * One stored entry with everything that fixes its place in a container: its key, its vector position and its two
 * order stamps. Enough to put a removed entry back exactly where it was, or to rebuild a container elsewhere.
 *
 * @param entry    the value
 * @param key      its key in the KEY view, or null
 * @param position its vector position, or -1 without a VECTOR view
 * @param written  insertion stamp (FIFO/LIFO order); unique within the container
 * @param used     last-use stamp (LRU order)
 */
public record PlacedEntry(Entry entry, String key, int position, long written, long used) {

    /** Validates the fields. */
    public PlacedEntry {
        Objects.requireNonNull(entry, "entry");
    }

    static PlacedEntry of(Node node) {
        return new PlacedEntry(node.entry, node.key, node.position, node.written, node.used);
    }
}
