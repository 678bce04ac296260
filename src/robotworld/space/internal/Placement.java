package robotworld.space.internal;

import java.util.ArrayList;
import java.util.List;

import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Order;

/** Puts items into a store: all-or-nothing for write, displacing for shift. */
final class Placement {

    private Placement() {
    }

    /**
     * Whether every item fits now: enough room, no key or position taken, no equal entry in a SET. The caller
     * has already rejected conflicts among the items themselves.
     */
    static boolean fits(EntryStore store, List<Item> items) {
        if (items.size() > store.room()) {
            return false;
        }
        for (Item item : items) {
            if (item.key() != null && store.byKey(item.key()) != null) {
                return false;
            }
            if (item.hasIndex() && store.atPosition(item.index()) != null) {
                return false;
            }
            if (store.isSet() && store.equalTo(item.entry()) != null) {
                return false;
            }
        }
        return true;
    }

    /**
     * Inserts items that {@link #fits fit}. Appended items go after every occupied position, including the
     * explicit positions of this same write, so they never collide with them.
     */
    static List<Entry> insertAll(EntryStore store, boolean vectorView, List<Item> items) {
        int append = vectorView ? appendStart(store, items) : -1;
        if (vectorView) {
            Validation.checkAppendPosition(append + appendCount(items) - 1); // before anything changes
        }
        List<Entry> written = new ArrayList<>(items.size());
        for (Item item : items) {
            int position = -1;
            if (vectorView) {
                position = item.hasIndex() ? item.index() : append++;
            }
            store.insert(item.entry(), item.key(), position);
            written.add(item.entry());
        }
        return written;
    }

    private static int appendCount(List<Item> items) {
        int count = 0;
        for (Item item : items) {
            if (!item.hasIndex()) {
                count++;
            }
        }
        return count;
    }

    private static int appendStart(EntryStore store, List<Item> items) {
        int start = store.vectorEnd();
        for (Item item : items) {
            if (item.hasIndex()) {
                start = Math.max(start, item.index() + 1);
            }
        }
        return start;
    }

    /**
     * Shifts items in one after another. Before each, whatever stands in its way is pushed out: the equal entry
     * (SET), the entry under its key, the entry at its position, and, if the container is still full, the entry
     * the base order would take next.
     *
     * @return the displaced entries, in displacement order
     */
    static List<Entry> shiftAll(EntryStore store, Order baseOrder, boolean vectorView, List<Item> items) {
        if (vectorView) {
            // conservative (displacement may lower the end), but checked before anything changes
            Validation.checkAppendPosition(appendStart(store, items) + appendCount(items) - 1);
        }
        List<Entry> displaced = new ArrayList<>();
        for (Item item : items) {
            if (store.isSet()) {
                displace(store, store.equalTo(item.entry()), displaced);
            }
            if (item.key() != null) {
                displace(store, store.byKey(item.key()), displaced);
            }
            if (item.hasIndex()) {
                displace(store, store.atPosition(item.index()), displaced);
            }
            if (store.room() == 0) {
                displace(store, store.first(baseOrder), displaced);
            }
            int position = -1;
            if (vectorView) {
                position = item.hasIndex() ? item.index() : store.vectorEnd();
            }
            store.insert(item.entry(), item.key(), position);
        }
        return displaced;
    }

    private static void displace(EntryStore store, Node node, List<Entry> displaced) {
        if (node != null) {
            store.remove(node);
            displaced.add(node.entry);
        }
    }
}
