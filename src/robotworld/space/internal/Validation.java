package robotworld.space.internal;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.InvalidOperationException;
import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.Uniqueness;

/**
 * Rejects, before any waiting, requests that could never succeed on a container, so they fail with
 * {@link InvalidOperationException} instead of blocking forever.
 */
final class Validation {

    /** Highest vector position; bounds the slot array a single write can make the container allocate. */
    static final int MAX_POSITION = (1 << 20) - 1;

    private Validation() {
    }

    static void checkSelectors(ContainerSpec spec, Selector[] selectors) {
        for (Selector selector : selectors) {
            if (selector == null) {
                throw new NullPointerException("selector");
            }
            if (selector instanceof Selector.Key && !spec.keyView()) {
                throw new InvalidOperationException("key selector on a container without a KEY view");
            }
            if (selector instanceof Selector.Vector && !spec.vectorView()) {
                throw new InvalidOperationException("vector selector on a container without a VECTOR view");
            }
            if (selector instanceof Selector.Vector byPosition && byPosition.index() > MAX_POSITION) {
                throw new InvalidOperationException("vector position " + byPosition.index()
                        + " beyond the maximum " + MAX_POSITION);
            }
            if (spec.isBounded() && selector.count() > spec.capacity()) {
                throw new InvalidOperationException("selector wants " + selector.count()
                        + " entries but the container holds at most " + spec.capacity());
            }
        }
    }

    /** Checks that a write can ever succeed: it fits the capacity and has no conflicts within itself. */
    static void checkWrite(ContainerSpec spec, List<Item> items) {
        checkItems(spec, items);
        if (spec.isBounded() && items.size() > spec.capacity()) {
            throw new InvalidOperationException("writing " + items.size()
                    + " entries into a container that holds at most " + spec.capacity());
        }
        Set<String> keys = new HashSet<>();
        Set<Integer> positions = new HashSet<>();
        Set<Entry> values = new HashSet<>();
        for (Item item : items) {
            if (item.key() != null && !keys.add(item.key())) {
                throw new InvalidOperationException("key '" + item.key() + "' appears twice in one write");
            }
            if (item.hasIndex() && !positions.add(item.index())) {
                throw new InvalidOperationException("vector position " + item.index() + " appears twice in one write");
            }
            if (spec.uniqueness() == Uniqueness.SET && !values.add(item.entry())) {
                throw new InvalidOperationException("entry " + item.entry() + " appears twice in one write to a SET");
            }
        }
    }

    /** Checks the items of a write or shift against the container's views. */
    static void checkItems(ContainerSpec spec, List<Item> items) {
        for (Item item : items) {
            if (item == null) {
                throw new NullPointerException("item");
            }
            if (item.key() != null && !spec.keyView()) {
                throw new InvalidOperationException("item with a key for a container without a KEY view");
            }
            if (item.hasIndex() && !spec.vectorView()) {
                throw new InvalidOperationException("item with a vector position for a container without a VECTOR view");
            }
            if (item.index() > MAX_POSITION) {
                throw new InvalidOperationException("vector position " + item.index() + " beyond the maximum "
                        + MAX_POSITION);
            }
        }
    }

    static void checkAppendPosition(int position) {
        if (position > MAX_POSITION) {
            throw new InvalidOperationException("vector is full: no position left after " + MAX_POSITION);
        }
    }
}
