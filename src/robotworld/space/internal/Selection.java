package robotworld.space.internal;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

import robotworld.space.Order;
import robotworld.space.Selector;

/**
 * Evaluates a selector chain against a store. The first selector chooses from the container through its
 * indexes (O(count) for orders, keys and positions; a scan for templates); each further selector refines the
 * previous choice. The result is null when some selector finds fewer entries than its count, which makes the
 * operation wait.
 */
final class Selection {

    private static final Comparator<Node> OLDEST_FIRST = Comparator.comparingLong(node -> node.written);
    private static final Comparator<Node> LEAST_USED_FIRST = Comparator.comparingLong(node -> node.used);
    private static final Comparator<Node> BY_POSITION = Comparator.comparingInt(node -> node.position);

    private Selection() {
    }

    /** The chosen nodes in result order, or null if not enough entries are present yet. */
    static List<Node> choose(EntryStore store, Order baseOrder, Selector[] selectors) {
        if (selectors.length == 0) {
            Node node = store.first(baseOrder);
            return node == null ? null : List.of(node);
        }
        List<Node> chosen = fromStore(store, baseOrder, selectors[0]);
        for (int i = 1; i < selectors.length && chosen != null; i++) {
            chosen = refine(chosen, baseOrder, selectors[i]);
        }
        return chosen;
    }

    private static List<Node> fromStore(EntryStore store, Order baseOrder, Selector selector) {
        if (selector instanceof Selector.Ordered ordered) {
            int count = ordered.count();
            if (count == 1) {
                Node node = store.first(ordered.order());
                return node == null ? null : List.of(node);
            }
            if (count != Selector.ALL && count > store.size()) {
                return null;
            }
            return store.first(ordered.order(), count);
        }
        if (selector instanceof Selector.Key byKey) {
            Node node = store.byKey(byKey.key());
            if (node == null) {
                return byKey.count() == Selector.ALL ? List.of() : null;
            }
            return List.of(node);
        }
        if (selector instanceof Selector.Vector byPosition) {
            return fromVector(store, byPosition);
        }
        Selector.Matching matching = (Selector.Matching) selector;
        int count = matching.count();
        List<Node> chosen = new ArrayList<>(count == Selector.ALL ? 8 : count);
        store.visitInOrder(baseOrder, node -> {
            if (matching.template().matches(node.entry)) {
                chosen.add(node);
            }
            return count == Selector.ALL || chosen.size() < count;
        });
        return count != Selector.ALL && chosen.size() < count ? null : chosen;
    }

    private static List<Node> fromVector(EntryStore store, Selector.Vector selector) {
        int start = selector.index();
        if (selector.count() == Selector.ALL) {
            List<Node> chosen = new ArrayList<>();
            for (int position = start; position < store.vectorEnd(); position++) {
                Node node = store.atPosition(position);
                if (node != null) {
                    chosen.add(node);
                }
            }
            return chosen;
        }
        List<Node> chosen = new ArrayList<>(selector.count());
        for (int position = start; position < start + selector.count(); position++) {
            Node node = store.atPosition(position);
            if (node == null) {
                return null;
            }
            chosen.add(node);
        }
        return chosen;
    }

    private static List<Node> refine(List<Node> candidates, Order baseOrder, Selector selector) {
        List<Node> chosen = new ArrayList<>(candidates.size());
        int count = selector.count();
        if (selector instanceof Selector.Ordered ordered) {
            chosen.addAll(candidates);
            sort(chosen, ordered.order());
        } else if (selector instanceof Selector.Key byKey) {
            for (Node node : candidates) {
                if (byKey.key().equals(node.key)) {
                    chosen.add(node);
                }
            }
        } else if (selector instanceof Selector.Vector byPosition) {
            return refineByPosition(candidates, byPosition);
        } else {
            Selector.Matching matching = (Selector.Matching) selector;
            for (Node node : candidates) {
                if (matching.template().matches(node.entry)) {
                    chosen.add(node);
                }
            }
        }
        if (count == Selector.ALL) {
            return chosen;
        }
        return chosen.size() < count ? null : chosen.subList(0, count);
    }

    private static List<Node> refineByPosition(List<Node> candidates, Selector.Vector selector) {
        int start = selector.index();
        long stop = selector.count() == Selector.ALL ? Long.MAX_VALUE : (long) start + selector.count();
        List<Node> chosen = new ArrayList<>();
        for (Node node : candidates) {
            if (node.position >= start && node.position < stop) {
                chosen.add(node);
            }
        }
        chosen.sort(BY_POSITION);
        if (selector.count() != Selector.ALL && chosen.size() < selector.count()) {
            return null; // some position in the range is not among the candidates
        }
        return chosen;
    }

    private static void sort(List<Node> nodes, Order order) {
        switch (order) {
            case FIFO -> nodes.sort(OLDEST_FIRST);
            case LIFO -> nodes.sort(OLDEST_FIRST.reversed());
            case LRU -> nodes.sort(LEAST_USED_FIRST);
            case RANDOM -> Collections.shuffle(nodes, ThreadLocalRandom.current());
        }
    }
}
