package robotworld.space.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Selector;

/**
 * The entries of one container and what the operations do to them (select, read, take, write, shift, put back),
 * without any locking, waiting or notification: for an engine that provides those itself, like the clustered
 * space, which runs these inside a Hazelcast entry processor on the member that owns the container. The rules are
 * exactly those of the embedded space, since both use the same store, selection and placement code.
 *
 * <p>Every change is reported to the observer set with {@link #observe} as a {@link StoreChange}; replaying those
 * changes on a copy with {@link #apply} keeps the copy identical without copying the container. Not thread-safe.
 */
public final class ContainerContents {

    private final ContainerSpec spec;
    private final EntryStore store;
    private Consumer<StoreChange> observer;

    /** An empty container with this spec. */
    public ContainerContents(ContainerSpec spec) {
        this.spec = spec;
        this.store = new EntryStore(spec);
        store.replicate(new EntryStore.ChangeObserver() {
            @Override
            public void placed(Node node) {
                report(new StoreChange.Placed(PlacedEntry.of(node)));
            }

            @Override
            public void removed(Node node) {
                report(new StoreChange.Removed(node.written));
            }

            @Override
            public void touched(Node node) {
                report(new StoreChange.Touched(node.written, node.used));
            }
        });
    }

    /**
     * Rebuilds a container from a {@link #snapshot()} and the {@link #clock()} it was taken with.
     */
    public static ContainerContents load(ContainerSpec spec, long clock, List<PlacedEntry> entries) {
        ContainerContents contents = new ContainerContents(spec);
        for (PlacedEntry placed : entries) {
            contents.store.placeReplica(placed.entry(), placed.key(), placed.position(), placed.written(),
                    placed.used());
        }
        contents.store.advanceClock(clock);
        return contents;
    }

    public ContainerSpec spec() {
        return spec;
    }

    /** Sends every later change to {@code changes} (null: to nobody). */
    public void observe(Consumer<StoreChange> changes) {
        this.observer = changes;
    }

    private void report(StoreChange change) {
        Consumer<StoreChange> target = observer;
        if (target != null) {
            target.accept(change);
        }
    }

    // ---- checks that come before any waiting ----

    /** @throws robotworld.space.InvalidOperationException if these selectors can never be satisfied here */
    public static void checkSelectors(ContainerSpec spec, Selector[] selectors) {
        Validation.checkSelectors(spec, selectors);
    }

    /** @throws robotworld.space.InvalidOperationException if this write can never succeed here */
    public static void checkWrite(ContainerSpec spec, List<Item> items) {
        Validation.checkWrite(spec, items);
    }

    /** @throws robotworld.space.InvalidOperationException if these items use a view the container lacks */
    public static void checkItems(ContainerSpec spec, List<Item> items) {
        Validation.checkItems(spec, items);
    }

    // ---- state ----

    public int size() {
        return store.size();
    }

    /** The latest order stamp handed out; part of a snapshot. */
    public long clock() {
        return store.clock();
    }

    /** Every entry with its place, oldest written first. */
    public List<PlacedEntry> snapshot() {
        List<PlacedEntry> entries = new ArrayList<>(store.size());
        store.visitByInsertion(node -> {
            entries.add(PlacedEntry.of(node));
            return true;
        });
        return entries;
    }

    /** Every entry with its place, in the order {@code order} visits them (RANDOM: from a random start). */
    public List<PlacedEntry> snapshot(robotworld.space.Order order) {
        List<PlacedEntry> entries = new ArrayList<>(store.size());
        store.visitInOrder(order, node -> {
            entries.add(PlacedEntry.of(node));
            return true;
        });
        return entries;
    }

    // ---- the operations' effects ----

    /** The selected entries, now counted as used; null if the selectors do not find enough. */
    public List<Entry> read(Selector[] selectors) {
        List<Node> chosen = Selection.choose(store, spec.order(), selectors);
        if (chosen == null) {
            return null;
        }
        List<Entry> entries = entriesOf(chosen);
        for (Node node : chosen) {
            store.touch(node);
        }
        return entries;
    }

    /** Removes the selected entries and returns them with their places (to undo); null if not enough. */
    public List<PlacedEntry> remove(Selector[] selectors) {
        List<Node> chosen = Selection.choose(store, spec.order(), selectors);
        if (chosen == null) {
            return null;
        }
        List<PlacedEntry> removed = new ArrayList<>(chosen.size());
        for (Node node : chosen) {
            removed.add(PlacedEntry.of(node));
        }
        for (Node node : chosen) {
            store.remove(node);
        }
        return removed;
    }

    /** Writes all items if they all fit now; whether they did. The caller checked {@link #checkWrite}. */
    public boolean write(List<Item> items) {
        if (!Placement.fits(store, items)) {
            return false;
        }
        Placement.insertAll(store, spec.vectorView(), items);
        return true;
    }

    /** Shifts the items in; returns what they displaced. The caller checked {@link #checkItems}. */
    public List<Entry> shift(List<Item> items) {
        return List.copyOf(Placement.shiftAll(store, spec.order(), spec.vectorView(), items));
    }

    /** Puts removed entries back where they were, if they all fit now; whether they did. */
    public boolean restore(List<PlacedEntry> removed) {
        List<Node> nodes = new ArrayList<>(removed.size());
        for (PlacedEntry placed : removed) {
            Node node = new Node(placed.entry(), placed.key(), placed.position(), placed.written());
            node.used = placed.used();
            nodes.add(node);
        }
        if (!store.canRestore(nodes)) {
            return false;
        }
        for (Node node : nodes) {
            store.restore(node);
        }
        return true;
    }

    /** Removes every entry (the container is being destroyed); not reported as changes. */
    public void clear() {
        store.clear();
    }

    /** Replays a change another copy reported. */
    public void apply(StoreChange change) {
        Consumer<StoreChange> saved = observer;
        observer = null; // a replica reports nothing
        try {
            if (change instanceof StoreChange.Placed placed) {
                PlacedEntry entry = placed.entry();
                store.placeReplica(entry.entry(), entry.key(), entry.position(), entry.written(), entry.used());
            } else if (change instanceof StoreChange.Removed removed) {
                store.removeReplica(removed.written());
            } else if (change instanceof StoreChange.Touched touched) {
                store.touchReplica(touched.written(), touched.used());
            }
        } finally {
            observer = saved;
        }
    }

    private static List<Entry> entriesOf(List<Node> nodes) {
        Entry[] entries = new Entry[nodes.size()];
        for (int i = 0; i < entries.length; i++) {
            entries[i] = nodes.get(i).entry;
        }
        return List.of(entries);
    }
}
