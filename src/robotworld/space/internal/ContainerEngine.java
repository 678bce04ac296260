package robotworld.space.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;

import robotworld.space.ContainerDestroyedException;
import robotworld.space.ContainerInfo;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Removal;
import robotworld.space.Selector;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/**
 * One container: its entries, its lock, its blocked operations and its subscriptions. Every operation runs
 * entirely under the container's own lock (there is no space-wide lock on the data path), which makes the
 * operations on one container linearizable. Notifications are queued inside the same critical section, so
 * their order is the operations' order.
 */
public final class ContainerEngine {

    private static final System.Logger LOG = System.getLogger(ContainerEngine.class.getName());

    private final ContainerRef ref;
    private final ContainerSpec spec;
    private final ReentrantLock lock = new ReentrantLock();
    private final EntryStore store;
    private final NotificationHub hub;
    private final Delivery delivery;
    private final int queueCapacity;
    /** Oldest first. */
    private final WaiterQueue waiters = new WaiterQueue();
    /** Thread-less waiters served in the current critical section, whose completions run after it. */
    private List<Waiter> ready;
    private long sequence;
    /** Null while alive; otherwise how later callers fail. */
    private Supplier<SpaceException> gone;

    ContainerEngine(ContainerRef ref, ContainerSpec spec, Delivery delivery, int queueCapacity) {
        this.ref = ref;
        this.spec = spec;
        this.store = new EntryStore(spec);
        this.hub = new NotificationHub(ref);
        this.delivery = delivery;
        this.queueCapacity = queueCapacity;
    }

    public ContainerRef ref() {
        return ref;
    }

    public ContainerSpec spec() {
        return spec;
    }

    // ---- operations ----

    /** read, take or destroy. */
    public List<Entry> retrieve(Operation operation, Timeout timeout, Selector[] selectors) {
        Validation.checkSelectors(spec, selectors);
        boolean mutates = operation != Operation.READ;
        @SuppressWarnings("unchecked")
        List<Entry> result = (List<Entry>) execute(timeout, mutates, () -> tryRetrieve(operation, selectors),
                keyOf(selectors), List.of());
        return result;
    }

    /**
     * take or destroy whose effect can be undone until the caller lets go of the {@link Removal}: a server uses
     * it to put entries back when the client that asked for them never confirmed that it received them.
     */
    public Removal removeWithReceipt(Operation operation, Timeout timeout, Selector[] selectors) {
        if (operation != Operation.TAKE && operation != Operation.DESTROY) {
            throw new IllegalArgumentException("only take and destroy remove entries: " + operation);
        }
        Validation.checkSelectors(spec, selectors);
        return (Removal) execute(timeout, true, () -> tryRemove(operation, selectors), keyOf(selectors), List.of());
    }

    public void write(Timeout timeout, List<Item> items) {
        Validation.checkWrite(spec, items);
        if (items.isEmpty()) {
            return;
        }
        execute(timeout, true, () -> tryWrite(items), null, keysOf(items));
    }

    public List<Entry> shift(List<Item> items) {
        Validation.checkItems(spec, items);
        if (items.isEmpty()) {
            return List.of();
        }
        @SuppressWarnings("unchecked")
        List<Entry> displaced = (List<Entry>) execute(Timeout.TRY_ONCE, true, () -> doShift(items), null,
                keysOf(items));
        return displaced;
    }

    private List<Entry> tryRetrieve(Operation operation, Selector[] selectors) {
        List<Node> chosen = Selection.choose(store, spec.order(), selectors);
        if (chosen == null) {
            return null;
        }
        List<Entry> entries = entriesOf(chosen);
        for (Node node : chosen) {
            if (operation == Operation.READ) {
                store.touch(node);
            } else {
                store.remove(node);
            }
        }
        published(operation, entries, List.of());
        return entries;
    }

    private Removal tryRemove(Operation operation, Selector[] selectors) {
        List<Node> chosen = Selection.choose(store, spec.order(), selectors);
        if (chosen == null) {
            return null;
        }
        List<Entry> entries = entriesOf(chosen);
        for (Node node : chosen) {
            store.remove(node);
        }
        published(operation, entries, List.of());
        return new UndoableRemoval(entries, List.copyOf(chosen));
    }

    /** Puts removed nodes back if they all fit now; announced as a write. Call under the lock. */
    private boolean tryRestore(List<Node> nodes) {
        if (!store.canRestore(nodes)) {
            return false;
        }
        for (Node node : nodes) {
            store.restore(node);
        }
        published(Operation.WRITE, entriesOf(nodes), List.of());
        return true;
    }

    /** A removal that remembers its nodes (with their order stamps, key and position) so it can be undone. */
    private final class UndoableRemoval implements Removal {
        private final List<Entry> entries;
        private final List<Node> nodes;
        /** Guarded by the container's lock. */
        private boolean restored;

        UndoableRemoval(List<Entry> entries, List<Node> nodes) {
            this.entries = entries;
            this.nodes = nodes;
        }

        @Override
        public List<Entry> entries() {
            return entries;
        }

        @Override
        public void restore() {
            lock.lock();
            try {
                if (restored || nodes.isEmpty()) {
                    return;
                }
                restored = true;
                if (gone != null) {
                    return; // the entries went with their container
                }
                List<String> keys = new ArrayList<>(nodes.size());
                for (Node node : nodes) {
                    if (node.key != null) {
                        keys.add(node.key);
                    }
                }
                if (tryRestore(nodes)) {
                    if (!waiters.isEmpty()) {
                        serveWaiters(keys);
                    }
                } else {
                    // nobody waits for this thread-less waiter: it is served first once the entries fit again
                    waiters.addFirst(new Waiter(() -> tryRestore(nodes) ? Boolean.TRUE : null, true,
                            lock.newCondition(), null, keys));
                }
            } finally {
                unlock();
            }
        }
    }

    private Object tryWrite(List<Item> items) {
        if (!Placement.fits(store, items)) {
            return null;
        }
        List<Entry> written = Placement.insertAll(store, spec.vectorView(), items);
        published(Operation.WRITE, written, List.of());
        return Boolean.TRUE;
    }

    private List<Entry> doShift(List<Item> items) {
        List<Entry> displaced = List.copyOf(Placement.shiftAll(store, spec.order(), spec.vectorView(), items));
        List<Entry> shifted = new ArrayList<>(items.size());
        for (Item item : items) {
            shifted.add(item.entry());
        }
        published(Operation.SHIFT, List.copyOf(shifted), displaced);
        return displaced;
    }

    private static List<Entry> entriesOf(List<Node> nodes) {
        if (nodes.size() == 1) {
            return List.of(nodes.get(0).entry);
        }
        Entry[] entries = new Entry[nodes.size()];
        for (int i = 0; i < entries.length; i++) {
            entries[i] = nodes.get(i).entry;
        }
        return List.of(entries);
    }

    /** Every completed operation gets the next sequence number; observers hear of those that touched entries. */
    private void published(Operation operation, List<Entry> entries, List<Entry> displaced) {
        long position = ++sequence;
        if (!entries.isEmpty()) {
            hub.publish(operation, entries, displaced, position);
        }
    }

    // ---- blocking ----

    private Object execute(Timeout timeout, boolean mutates, Waiter.Attempt attempt, String key,
                           List<String> adds) {
        lock.lock();
        try {
            failIfGone();
            Object result = attempt.tryOnce();
            if (result != null) {
                if (mutates && !waiters.isEmpty()) {
                    serveWaiters(adds);
                }
                return result;
            }
            if (timeout.isTryOnce()) {
                throw new SpaceTimeoutException("not possible at once on " + describe());
            }
            Waiter waiter = new Waiter(attempt, mutates, lock.newCondition(), key, adds);
            waiters.addLast(waiter);
            return await(waiter, timeout);
        } finally {
            unlock();
        }
    }

    // ---- waiting without a thread (SpaceEngine) ----

    /** read, take or destroy that waits without a thread; take and destroy hand over a {@link Removal}. */
    public SpaceEngine.Pending retrieveLater(Operation operation, Timeout timeout, Selector[] selectors,
                                             SpaceEngine.Completion<Object> done) {
        Validation.checkSelectors(spec, selectors);
        if (operation == Operation.READ) {
            return executeLater(timeout, false, () -> tryRetrieve(operation, selectors), done, keyOf(selectors),
                    List.of());
        }
        if (operation != Operation.TAKE && operation != Operation.DESTROY) {
            throw new IllegalArgumentException("not a retrieving operation: " + operation);
        }
        return executeLater(timeout, true, () -> tryRemove(operation, selectors), done, keyOf(selectors), List.of());
    }

    /** write that waits without a thread; completes with {@code Boolean.TRUE}. */
    public SpaceEngine.Pending writeLater(Timeout timeout, List<Item> items, SpaceEngine.Completion<Object> done) {
        Validation.checkWrite(spec, items);
        if (items.isEmpty()) {
            done.completed(Boolean.TRUE);
            return SpaceEngine.Pending.DONE;
        }
        return executeLater(timeout, true, () -> tryWrite(items), done, null, keysOf(items));
    }

    private SpaceEngine.Pending executeLater(Timeout timeout, boolean mutates, Waiter.Attempt attempt,
                                             SpaceEngine.Completion<Object> done, String key, List<String> adds) {
        Object result;
        SpaceException failure = null;
        lock.lock();
        try {
            failIfGone();
            result = attempt.tryOnce();
            if (result != null) {
                if (mutates && !waiters.isEmpty()) {
                    serveWaiters(adds);
                }
            } else if (timeout.isTryOnce()) {
                failure = new SpaceTimeoutException("not possible at once on " + describe());
            } else {
                Waiter waiter = new Waiter(attempt, mutates, null, done, key, adds);
                waiters.addLast(waiter);
                if (!timeout.isInfinite()) {
                    waiter.expiry = delivery.timeout(() -> expire(waiter, timeout),
                            TimeUnit.MILLISECONDS.toNanos(timeout.millis()));
                }
                return () -> withdraw(waiter);
            }
        } finally {
            unlock();
        }
        if (failure != null) {
            done.failed(failure);
        } else {
            done.completed(result);
        }
        return SpaceEngine.Pending.DONE;
    }

    private void expire(Waiter waiter, Timeout timeout) {
        lock.lock();
        try {
            if (!waiter.done) {
                waiters.remove(waiter);
                complete(waiter, null, new SpaceTimeoutException("timed out after " + timeout + " on " + describe()));
            }
        } finally {
            unlock();
        }
    }

    private boolean withdraw(Waiter waiter) {
        lock.lock();
        try {
            if (waiter.done) {
                return false;
            }
            waiters.remove(waiter);
            waiter.done = true;
            if (waiter.expiry != null) {
                waiter.expiry.cancel();
            }
            return true;
        } finally {
            unlock();
        }
    }

    /** Hands a waiter its outcome under the lock; a thread-less waiter's completion runs once the lock is released. */
    private void complete(Waiter waiter, Object result, SpaceException failure) {
        if (failure != null) {
            waiter.fail(failure);
        } else {
            waiter.succeed(result);
        }
        if (waiter.completion != null) {
            if (ready == null) {
                ready = new ArrayList<>(2);
            }
            ready.add(waiter);
        }
    }

    /**
     * Releases the lock, then calls the completions of the thread-less waiters this critical section served, so
     * they run on the thread that served them but never inside the lock.
     */
    private void unlock() {
        List<Waiter> fire = null;
        if (ready != null && lock.getHoldCount() == 1) {
            fire = ready;
            ready = null;
        }
        lock.unlock();
        if (fire != null) {
            for (Waiter waiter : fire) {
                try {
                    waiter.fire();
                } catch (RuntimeException e) {
                    LOG.log(System.Logger.Level.WARNING, "a completion of a waiting operation on " + describe()
                            + " failed", e);
                }
            }
        }
    }

    private Object await(Waiter waiter, Timeout timeout) {
        long deadline = timeout.isInfinite() ? 0 : System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeout.millis());
        while (!waiter.done) {
            try {
                if (timeout.isInfinite()) {
                    waiter.wakeUp.await();
                } else {
                    long left = deadline - System.nanoTime();
                    if (left <= 0) {
                        waiters.remove(waiter);
                        throw new SpaceTimeoutException("timed out after " + timeout + " on " + describe());
                    }
                    waiter.wakeUp.awaitNanos(left);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                if (waiter.done) {
                    break; // the operation already happened: hand over its result rather than lose it
                }
                waiters.remove(waiter);
                throw new SpaceInterruptedException("interrupted while waiting on " + describe(), e);
            }
        }
        if (waiter.failure != null) {
            throw waiter.failure;
        }
        return waiter.result;
    }

    /**
     * Retries blocked operations, oldest first: those that any change may unblock, and those waiting for one of the
     * keys that just received an entry ({@code keys}). After one that changed the container succeeds, starts again
     * from the oldest, since the change may have unblocked an operation that was skipped before.
     */
    private void serveWaiters(java.util.Collection<String> keys) {
        java.util.Collection<String> touched = keys;
        boolean changed = true;
        while (changed && !waiters.isEmpty()) {
            changed = false;
            for (Waiter waiter : waiters.candidates(touched)) {
                Object result;
                try {
                    result = waiter.attempt.tryOnce();
                } catch (SpaceException e) {
                    waiters.remove(waiter);
                    complete(waiter, null, e);
                    continue;
                }
                if (result != null) {
                    waiters.remove(waiter);
                    complete(waiter, result, null);
                    if (waiter.mutates) {
                        if (!waiter.adds.isEmpty()) {
                            java.util.Set<String> more = new java.util.HashSet<>(touched);
                            more.addAll(waiter.adds);
                            touched = more;
                        }
                        changed = true;
                        break;
                    }
                }
            }
        }
    }

    /** The key of a selector chain that is exactly one key selector for one entry, else null. */
    private static String keyOf(Selector[] selectors) {
        if (selectors.length == 1 && selectors[0] instanceof Selector.Key key && key.count() == 1) {
            return key.key();
        }
        return null;
    }

    /** The keys of the items that carry one. */
    private static List<String> keysOf(List<Item> items) {
        List<String> keys = null;
        for (Item item : items) {
            if (item.key() != null) {
                if (keys == null) {
                    keys = new ArrayList<>(items.size());
                }
                keys.add(item.key());
            }
        }
        return keys == null ? List.of() : keys;
    }

    // ---- notifications ----

    public Subscription subscribe(Set<Operation> operations, NotificationMode mode, Timeout timeout,
                                  NotificationListener listener) {
        lock.lock();
        try {
            failIfGone();
            QueuedSubscription subscription = new QueuedSubscription(ref, operations, mode, timeout, listener,
                    queueCapacity, delivery, hub::remove);
            hub.add(subscription);
            subscription.start();
            return subscription;
        } finally {
            unlock();
        }
    }

    // ---- lifecycle ----

    /** Destroys the container: waiters fail, observers get DESTROY_CONTAINER (if asked) and their end. */
    void destroy() {
        lock.lock();
        try {
            if (gone != null) {
                return;
            }
            gone = () -> new ContainerNotFoundException("container " + ref + " was destroyed");
            failWaiters(() -> new ContainerDestroyedException("container " + ref + " was destroyed while waiting"));
            hub.publish(Operation.DESTROY_CONTAINER, List.of(), List.of(), ++sequence);
            hub.endAll(SubscriptionEnd.CONTAINER_DESTROYED);
            store.clear();
        } finally {
            unlock();
        }
    }

    /** Closes the container with its space: waiters fail, subscriptions end. */
    void close() {
        lock.lock();
        try {
            if (gone != null) {
                return;
            }
            gone = () -> new SpaceClosedException("the space is closed");
            failWaiters(gone);
            hub.endAll(SubscriptionEnd.SPACE_CLOSED);
        } finally {
            unlock();
        }
    }

    private void failWaiters(Supplier<? extends SpaceException> error) {
        for (Waiter waiter : waiters.drain()) {
            complete(waiter, null, error.get());
        }
    }

    private void failIfGone() {
        if (gone != null) {
            throw gone.get();
        }
    }

    /** The number of the latest operation on this container (see {@link robotworld.space.Notification#sequence}). */
    public long sequence() {
        lock.lock();
        try {
            failIfGone();
            return sequence;
        } finally {
            unlock();
        }
    }

    public ContainerInfo info() {
        lock.lock();
        try {
            failIfGone();
            return new ContainerInfo(ref, spec, store.size(), waiters.size(), hub.count());
        } finally {
            unlock();
        }
    }

    private String describe() {
        return spec.name() == null ? ref.toString() : "container '" + spec.name() + "' (" + ref + ")";
    }
}
