package robotworld.cluster;

import java.lang.System.Logger.Level;
import java.net.URI;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

import com.hazelcast.core.HazelcastInstance;

import robotworld.space.AsyncTakes;
import robotworld.space.ClusterHealth;
import robotworld.space.ContainerDestroyedException;
import robotworld.space.ContainerInfo;
import robotworld.space.ContainerNameTakenException;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.InvalidOperationException;
import robotworld.space.Item;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Removal;
import robotworld.space.Selector;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceTimeoutException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.Subscription;
import robotworld.space.Timeout;
import robotworld.space.internal.QueuedSubscription;

/**
 * A space kept by a cluster, used through one member: the {@link Capi} of a {@link ClusterMember#openSpace}. Every
 * handle on every member of the cluster sees the same containers, with the semantics of the embedded space (see
 * the package description for how, and for what a member's failure does). Closing a handle ends its own waiting
 * calls and subscriptions; the space and the member go on.
 */
public final class ClusterSpace implements SpaceEngine, AsyncTakes {

    private static final System.Logger LOG = System.getLogger(ClusterSpace.class.getName());

    private final ClusterNode node;
    private final String name;
    private final URI uri;
    private final int queueCapacity;
    private final Set<LocalWaiter> waiting = ConcurrentHashMap.newKeySet();
    private final Set<ClusterSubscription> subscriptions = ConcurrentHashMap.newKeySet();
    private final Set<AsyncWaiter<?>> waitingWithoutThreads = ConcurrentHashMap.newKeySet();
    private final ClusterReceipts receipts = new ClusterReceipts(this);
    private volatile boolean closed;

    ClusterSpace(ClusterNode node, String name, int queueCapacity) {
        if (queueCapacity < 1) {
            throw new IllegalArgumentException("notification queue capacity must be at least 1");
        }
        this.node = node;
        this.name = name;
        this.uri = URI.create("cluster:" + node.options().clusterName() + "/" + name);
        this.queueCapacity = queueCapacity;
    }

    /** {@code cluster:<cluster name>/<space name>}: the same on every member, so crefs work on any of them. */
    @Override
    public URI spaceUri() {
        return uri;
    }

    String name() {
        return name;
    }

    /** The members this member sees and whether Hazelcast reports every partition's backups in place. */
    @Override
    public Optional<ClusterHealth> clusterHealth() {
        HazelcastInstance hazelcast = node.hazelcast();
        return Optional.of(new ClusterHealth(hazelcast.getCluster().getMembers().size(),
                hazelcast.getPartitionService().isClusterSafe()));
    }

    ClusterNode node() {
        return node;
    }

    // ---- naming service ----

    @Override
    public ContainerRef createContainer(ContainerSpec spec) {
        Objects.requireNonNull(spec, "spec");
        checkOpen();
        long deadline = allowance();
        while (true) {
            String id = node.newContainerId();
            node.createRecord(name, newRecord(id, spec), deadline, uri);
            if (spec.name() == null) {
                return ref(id);
            }
            NameRecord holder = node.nameCall(name, spec.name(), NameCall.claim(new NameRecord(id, spec)), deadline,
                    uri);
            if (holder.id().equals(id)) {
                return ref(id);
            }
            node.deleteRecord(name, id, deadline, uri);
            if (isAlive(holder.id(), deadline)) {
                throw new ContainerNameTakenException("a container named '" + spec.name() + "' exists");
            }
            releaseStaleName(spec.name(), holder.id(), deadline);
        }
    }

    @Override
    public ContainerRef lookupContainer(String containerName) {
        Objects.requireNonNull(containerName, "name");
        checkOpen();
        NameRecord holder = node.lookupName(name, containerName, allowance(), uri);
        if (holder == null) {
            throw new ContainerNotFoundException("no container named '" + containerName + "'");
        }
        return ref(holder.id());
    }

    @Override
    public ContainerRef lookupOrCreateContainer(ContainerSpec spec) {
        Objects.requireNonNull(spec, "spec");
        if (spec.name() == null) {
            throw new IllegalArgumentException("lookup-or-create needs a named spec");
        }
        checkOpen();
        long deadline = allowance();
        while (true) {
            NameRecord holder = node.lookupName(name, spec.name(), deadline, uri);
            if (holder == null) {
                String id = node.newContainerId();
                node.createRecord(name, newRecord(id, spec), deadline, uri);
                holder = node.nameCall(name, spec.name(), NameCall.claim(new NameRecord(id, spec)), deadline, uri);
                if (holder.id().equals(id)) {
                    return ref(id);
                }
                node.deleteRecord(name, id, deadline, uri); // another participant won the race: use theirs
            }
            if (!isAlive(holder.id(), deadline)) {
                releaseStaleName(spec.name(), holder.id(), deadline);
                continue;
            }
            if (!holder.spec().equals(spec)) {
                throw new ContainerNameTakenException("container '" + spec.name()
                        + "' exists with a different spec: " + holder.spec());
            }
            return ref(holder.id());
        }
    }

    @Override
    public void destroyContainer(ContainerRef container) {
        String id = resolve(container);
        checkOpen();
        long deadline = allowance();
        Outcome outcome = once(id, call -> ContainerCall.destroyContainer(call), deadline);
        failIfMissing(outcome, container);
        if (outcome.spec != null && outcome.spec.name() != null) {
            node.nameCall(name, outcome.spec.name(), NameCall.release(id), deadline, uri);
        }
    }

    @Override
    public ContainerInfo describeContainer(ContainerRef container) {
        String id = resolve(container);
        checkOpen();
        Outcome outcome = node.call(name, id, ContainerCall.describe(), allowance(), uri);
        failIfMissing(outcome, container);
        return new ContainerInfo(container, outcome.spec, outcome.size, outcome.blocked, outcome.subscriptions);
    }

    private ContainerRecord newRecord(String id, ContainerSpec spec) {
        return new ContainerRecord(id, spec, node.options().journalCapacity());
    }

    private boolean isAlive(String id, long deadline) {
        Outcome outcome = node.call(name, id, ContainerCall.describe(), deadline, uri);
        return outcome.status == Outcome.Status.DONE;
    }

    /** A name still points at a destroyed container (its destroyer died before freeing it): free it now. */
    private void releaseStaleName(String containerName, String id, long deadline) {
        LOG.log(Level.INFO, "freeing name '" + containerName + "' of destroyed container " + id);
        node.nameCall(name, containerName, NameCall.release(id), deadline, uri);
    }

    // ---- operations ----

    @Override
    public List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors) {
        return retrieve(ContainerCall.Kind.READ, container, timeout, selectors);
    }

    @Override
    public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
        return retrieve(ContainerCall.Kind.TAKE, container, timeout, selectors);
    }

    @Override
    public int destroy(ContainerRef container, Timeout timeout, Selector... selectors) {
        return retrieve(ContainerCall.Kind.DESTROY, container, timeout, selectors).size();
    }

    private List<Entry> retrieve(ContainerCall.Kind kind, ContainerRef container, Timeout timeout,
                                 Selector[] selectors) {
        return result(retrieveOutcome(kind, container, timeout, selectors), container);
    }

    private Outcome retrieveOutcome(ContainerCall.Kind kind, ContainerRef container, Timeout timeout,
                                    Selector[] selectors) {
        String id = resolve(container);
        Objects.requireNonNull(timeout, "timeout");
        Selector[] chain = checkedSelectors(selectors);
        return perform(id, container, timeout, (call, wait) -> ContainerCall.retrieve(kind, call, chain, wait));
    }

    private static Selector[] checkedSelectors(Selector[] selectors) {
        for (Selector selector : selectors) {
            Objects.requireNonNull(selector, "selector");
        }
        return selectors.clone();
    }

    @Override
    public void write(ContainerRef container, Timeout timeout, List<Item> items) {
        String id = resolve(container);
        Objects.requireNonNull(timeout, "timeout");
        List<Item> copy = List.copyOf(items);
        result(perform(id, container, timeout, (call, wait) -> ContainerCall.write(call, copy, wait)), container);
    }

    @Override
    public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
        String id = resolve(container);
        Objects.requireNonNull(timeout, "timeout");
        List<Item> copy = List.copyOf(items);
        checkOpen();
        Outcome outcome = once(id, call -> ContainerCall.shift(call, copy), allowance());
        return result(outcome, container);
    }

    /** A call that never waits in the container, with its own call id. */
    private Outcome once(String id, Function<OpId, ContainerCall> request, long deadline) {
        OpId call = node.begin();
        try {
            return node.call(name, id, request.apply(call), deadline, uri);
        } finally {
            node.end(call);
        }
    }

    /** Builds a call from its id and how long it may wait in the container (0 try once, -1 infinite). */
    @FunctionalInterface
    private interface Request {
        ContainerCall build(OpId call, long waitMillis);
    }

    /**
     * Runs an operation that may wait: done at once, or queued in its container while this thread sleeps until a
     * wake-up (or, now and then, without one) and collects the result. At its deadline, on an interrupt, or when
     * the handle closes, the waiter is withdrawn, unless the container served it meanwhile: then its result is
     * returned rather than lost.
     */
    private Outcome perform(String id, ContainerRef container, Timeout timeout, Request request) {
        checkOpen();
        long start = System.nanoTime();
        long deadline = timeout.isInfinite() ? Long.MAX_VALUE
                : start + TimeUnit.MILLISECONDS.toNanos(timeout.millis());
        while (true) {
            OpId call = node.begin();
            LocalWaiter waiter = timeout.isTryOnce() ? null : node.register(call);
            try {
                if (waiter != null) {
                    waiting.add(waiter);
                    if (closed) {
                        throw new SpaceClosedException("the space handle is closed");
                    }
                }
                long waitMillis = timeout.isInfinite() ? -1 : timeout.isTryOnce() ? 0
                        : Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime()));
                Outcome outcome = node.call(name, id, request.build(call, waitMillis), allowance(), uri);
                node.end(call);
                if (outcome.status == Outcome.Status.NOT_POSSIBLE) {
                    throw new SpaceTimeoutException("not possible at once on " + container);
                }
                if (outcome.status != Outcome.Status.QUEUED) {
                    result(outcome, container); // throws what failed
                    return outcome;
                }
                Outcome result = await(id, container, waiter, deadline, timeout);
                if (result != null) {
                    result(result, container);
                    return result;
                }
                // the container forgot the waiter (this member was cut off meanwhile): nothing happened; queue again
            } finally {
                node.end(call);
                if (waiter != null) {
                    waiting.remove(waiter);
                    node.unregister(waiter);
                }
            }
        }
    }

    private enum GiveUp { TIMEOUT, INTERRUPTED, CLOSED }

    /** Waits for a queued operation; its outcome, or null if the container no longer knows it. */
    private Outcome await(String id, ContainerRef container, LocalWaiter waiter, long deadline,
                              Timeout timeout) {
        long nap = ClusterNode.FIRST_NAP_NANOS;
        long nextLook = System.nanoTime() + nap;
        while (true) {
            long now = System.nanoTime();
            long until = deadline - nextLook < 0 ? deadline : nextLook;
            boolean woken;
            try {
                woken = waiter.await(until - now);
            } catch (InterruptedException e) {
                return giveUp(id, container, waiter, GiveUp.INTERRUPTED, timeout);
            }
            if (waiter.isClosed() || closed) {
                return giveUp(id, container, waiter, GiveUp.CLOSED, timeout);
            }
            now = System.nanoTime();
            if (woken || now - nextLook >= 0) {
                Outcome look;
                try {
                    look = about(ContainerCall.Kind.COLLECT, id, waiter.id(), allowance());
                } catch (SpaceUnavailableException recovering) {
                    look = null; // the cluster is busy recovering: look again later
                }
                if (look != null) {
                    switch (look.status) {
                        case QUEUED -> {
                        }
                        case UNKNOWN -> {
                            return null;
                        }
                        case DESTROYED, NOT_FOUND -> throw destroyedWhileWaiting(container);
                        default -> {
                            return look;
                        }
                    }
                }
                nap = Math.min(nap * 2, ClusterNode.LONGEST_NAP_NANOS);
                nextLook = System.nanoTime() + nap;
            }
            if (deadline != Long.MAX_VALUE && System.nanoTime() - deadline >= 0) {
                return giveUp(id, container, waiter, GiveUp.TIMEOUT, timeout);
            }
        }
    }

    /** Withdraws a waiter; hands over its result if it was served meanwhile, else fails as {@code why} says. */
    private Outcome giveUp(String id, ContainerRef container, LocalWaiter waiter, GiveUp why, Timeout timeout) {
        Outcome outcome;
        try {
            outcome = about(ContainerCall.Kind.WITHDRAW, id, waiter.id(), allowance());
        } finally {
            if (why == GiveUp.INTERRUPTED) {
                Thread.currentThread().interrupt();
            }
        }
        return switch (outcome.status) {
            case WITHDRAWN, UNKNOWN -> throw switch (why) {
                case TIMEOUT -> new SpaceTimeoutException("timed out after " + timeout + " on " + container);
                case INTERRUPTED -> new SpaceInterruptedException("interrupted while waiting on " + container,
                        new InterruptedException());
                case CLOSED -> new SpaceClosedException("the space handle was closed while waiting on "
                        + container);
            };
            case DESTROYED, NOT_FOUND -> throw destroyedWhileWaiting(container);
            default -> outcome; // served before it could be withdrawn: never lose that
        };
    }

    /** A call about a waiter (collect or withdraw), with its own call id; not interruptible. */
    private Outcome about(ContainerCall.Kind kind, String id, OpId waiter, long deadline) {
        boolean interrupted = Thread.interrupted();
        OpId call = node.begin();
        try {
            return node.call(name, id, ContainerCall.about(kind, call, waiter), deadline, uri);
        } finally {
            node.end(call);
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** As {@link #about(ContainerCall.Kind, String, OpId, long)}, within the call allowance. */
    Outcome about(ContainerCall.Kind kind, String id, OpId waiter) {
        return about(kind, id, waiter, allowance());
    }

    /** Runs a call on container {@code id} within the call allowance. */
    Outcome call(String id, ContainerCall call) {
        return node.call(name, id, call, allowance(), uri);
    }

    /** Puts removed entries back into container {@code id} (an undone take or destroy). */
    void restore(String id, List<robotworld.space.internal.PlacedEntry> removed) {
        OpId call = node.begin();
        try {
            node.call(name, id, ContainerCall.restore(call, removed), allowance(), uri);
        } finally {
            node.end(call);
        }
    }

    private static ContainerDestroyedException destroyedWhileWaiting(ContainerRef container) {
        return new ContainerDestroyedException("container " + container + " was destroyed while waiting");
    }

    private static List<Entry> result(Outcome outcome, ContainerRef container) {
        return switch (outcome.status) {
            case DONE -> outcome.entries;
            case INVALID -> throw new InvalidOperationException(outcome.message);
            case NOT_FOUND, DESTROYED -> throw new ContainerNotFoundException("no container " + container
                    + " (destroyed, or never created)");
            case NOT_POSSIBLE -> throw new SpaceTimeoutException("not possible at once on " + container);
            case FAILED -> throw new robotworld.space.SpaceException("the cluster failed a call on " + container
                    + ": " + outcome.message);
            case CANCELLED -> throw new robotworld.space.CallCancelledException(outcome.message);
            default -> throw new IllegalStateException("unexpected outcome " + outcome + " on " + container);
        };
    }

    private static void failIfMissing(Outcome outcome, ContainerRef container) {
        if (outcome.status == Outcome.Status.NOT_FOUND || outcome.status == Outcome.Status.DESTROYED) {
            throw new ContainerNotFoundException("no container " + container + " (destroyed, or never created)");
        }
    }

    // ---- for servers (SpaceEngine) and programs that wait without threads (AsyncTakes) ----

    /** The cluster's calls cross the network: a server runs them on pool threads. */
    @Override
    public boolean callsMayBlock() {
        return true;
    }

    /** Every member's server hands out crefs with this space's URI, so they work on every member. */
    @Override
    public boolean sharedUri() {
        return true;
    }

    @Override
    public Removal removeWithReceipt(ContainerRef container, Operation operation, Timeout timeout,
                                     Selector... selectors) {
        Outcome outcome = retrieveOutcome(removal(operation), container, timeout, selectors);
        return new ClusterRemoval(this, container.id(), outcome.entries, outcome.removed, null);
    }

    private static ContainerCall.Kind removal(Operation operation) {
        return switch (operation) {
            case TAKE -> ContainerCall.Kind.TAKE;
            case DESTROY -> ContainerCall.Kind.DESTROY;
            default -> throw new IllegalArgumentException("only take and destroy remove entries: " + operation);
        };
    }

    @Override
    public long sequence(ContainerRef container) {
        String id = resolve(container);
        Outcome outcome = node.call(name, id, ContainerCall.describe(), allowance(), uri);
        failIfMissing(outcome, container);
        return outcome.sequence;
    }

    @Override
    public Pending readLater(ContainerRef container, Timeout timeout, Selector[] selectors,
                             Completion<List<Entry>> done) {
        return later(ContainerCall.Kind.READ, container, timeout, selectors, null, outcome -> outcome.entries, done);
    }

    @Override
    public Pending removeLater(ContainerRef container, Operation operation, Timeout timeout, Selector[] selectors,
                               Completion<Removal> done) {
        return removeLater(container, operation, timeout, selectors, null, done);
    }

    /** With a client's call id, the removal is held in its container under that id until it is confirmed. */
    @Override
    public Pending removeLater(ContainerRef container, Operation operation, Timeout timeout, Selector[] selectors,
                               String callId, Completion<Removal> done) {
        if (callId != null) {
            receipts.made(callId, resolve(container), true);
        }
        return later(removal(operation), container, timeout, selectors, callId,
                outcome -> new ClusterRemoval(this, container.id(), outcome.entries, outcome.removed, callId), done);
    }

    @Override
    public Pending writeLater(ContainerRef container, Timeout timeout, List<Item> items, Completion<Void> done) {
        return writeLater(container, timeout, items, null, done);
    }

    /** With a client's call id, the container remembers under it that the write happened. */
    @Override
    public Pending writeLater(ContainerRef container, Timeout timeout, List<Item> items, String callId,
                              Completion<Void> done) {
        String id = resolve(container);
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(done, "done");
        List<Item> copy = List.copyOf(items);
        if (callId != null) {
            receipts.made(callId, id, false);
        }
        return new AsyncWaiter<Void>(this, id, container, timeout, (call, wait) -> forClient(ContainerCall.write(call,
                copy, wait), callId), outcome -> null, done).start();
    }

    /** With a client's call id, the container remembers under it that the shift happened, and what it displaced. */
    @Override
    public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items, String callId) {
        if (callId == null) {
            return shift(container, timeout, items);
        }
        String id = resolve(container);
        Objects.requireNonNull(timeout, "timeout");
        List<Item> copy = List.copyOf(items);
        receipts.made(callId, id, false);
        Outcome outcome = once(id, call -> forClient(ContainerCall.shift(call, copy), callId), allowance());
        return result(outcome, container);
    }

    @Override
    public robotworld.space.CallReceipts receipts() {
        return receipts;
    }

    private ContainerCall forClient(ContainerCall call, String callId) {
        return callId == null ? call : call.forClient(callId, node.options().lease().toMillis());
    }

    /** A call about the receipts of several client calls on container {@code id}. */
    Outcome receiptsCall(String id, ContainerCall.Kind kind, List<String> callIds) {
        return once(id, call -> ContainerCall.receipts(kind, call, callIds), allowance());
    }

    /** A call about the receipt of one client call on container {@code id}. */
    Outcome receiptCall(String id, ContainerCall.Kind kind, String callId) {
        return once(id, call -> ContainerCall.receipt(kind, call, callId), allowance());
    }

    /** The container that knows client call {@code callId}, asking all of this space's containers; or null. */
    String findReceipt(String callId) {
        return node.findReceipt(name, callId, allowance(), uri);
    }

    /** In-process, a take needs no receipt: the entries are the result. */
    @Override
    public Pending takeLater(ContainerRef container, Timeout timeout, Selector[] selectors,
                             Completion<List<Entry>> done) {
        return later(ContainerCall.Kind.TAKE, container, timeout, selectors, null, outcome -> outcome.entries, done);
    }

    @Override
    public Pending shiftThenTakeLater(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                      Selector[] selectors, Completion<List<Entry>> done) {
        shift(shiftTo, timeout, items);
        return takeLater(takeFrom, timeout, selectors, done);
    }

    private <T> Pending later(ContainerCall.Kind kind, ContainerRef container, Timeout timeout, Selector[] selectors,
                              String callId, java.util.function.Function<Outcome, T> result, Completion<T> done) {
        String id = resolve(container);
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(done, "done");
        Selector[] chain = checkedSelectors(selectors);
        return new AsyncWaiter<>(this, id, container, timeout,
                (call, wait) -> forClient(ContainerCall.retrieve(kind, call, chain, wait), callId), result, done)
                .start();
    }

    /** Puts the held removal of client call {@code callId} back into container {@code id}. */
    void restoreReceipt(String id, String callId) {
        receiptCall(id, ContainerCall.Kind.RESTORE_RECEIPT, callId);
    }

    void track(AsyncWaiter<?> waiter) {
        waitingWithoutThreads.add(waiter);
        if (closed) {
            waiter.giveUp(new SpaceClosedException("the space handle is closed"));
        }
    }

    void untrack(AsyncWaiter<?> waiter) {
        waitingWithoutThreads.remove(waiter);
    }

    // ---- notifications ----

    @Override
    public Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode,
                                  Timeout timeout, NotificationListener listener) {
        String id = resolve(container);
        Objects.requireNonNull(operations, "operations");
        Objects.requireNonNull(mode, "mode");
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(listener, "listener");
        checkOpen();
        EventInbox inbox;
        do {
            inbox = node.inbox(name, id, key -> new EventInbox(this, id, container));
        } while (!inbox.opening());
        OpId subscriptionId = node.begin();
        ClusterSubscription subscription = new ClusterSubscription(this, id, subscriptionId, inbox);
        boolean opened = false;
        try {
            Outcome outcome = node.call(name, id, ContainerCall.about(ContainerCall.Kind.SUBSCRIBE, subscriptionId,
                    subscriptionId), allowance(), uri);
            failIfMissing(outcome, container);
            QueuedSubscription queued = new QueuedSubscription(container, operations, mode, timeout, listener,
                    queueCapacity, node.delivery(), ended -> {
                        subscriptions.remove(subscription);
                        subscription.onEnd();
                    });
            subscription.start(queued, outcome.sequence);
            subscriptions.add(subscription);
            queued.start();
            inbox.opened(subscription, outcome.chainTail);
            opened = true;
            if (closed) {
                subscription.endedBy(robotworld.space.SubscriptionEnd.SPACE_CLOSED);
            }
            return subscription;
        } finally {
            node.end(subscriptionId);
            if (!opened) {
                inbox.openFailed();
            }
        }
    }

    /** Takes a subscription off its container's list; failures are only logged (the container survives them). */
    void unregister(String container, OpId subscription) {
        OpId call = node.begin();
        try {
            node.call(name, container, ContainerCall.about(ContainerCall.Kind.UNSUBSCRIBE, call, subscription),
                    allowance(), uri);
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "could not unregister a subscription on " + container + ": " + e.getMessage());
        } finally {
            node.end(call);
        }
    }

    /** The sequence of the container's last journaled event, or -1 if it cannot be asked now. */
    long chainTailOf(String container) {
        try {
            return node.call(name, container, ContainerCall.describe(), allowance(), uri).chainTail;
        } catch (RuntimeException e) {
            return -1;
        }
    }

    Outcome readJournal(String container, long after, List<OpId> registered) {
        return node.call(name, container, ContainerCall.readJournal(after, registered), allowance(), uri);
    }

    // ---- lifecycle ----

    /** Ends this handle's waiting calls ({@link SpaceClosedException}) and subscriptions; the space goes on. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        for (LocalWaiter waiter : waiting) {
            waiter.close();
        }
        for (AsyncWaiter<?> waiter : List.copyOf(waitingWithoutThreads)) {
            waiter.giveUp(new SpaceClosedException("the space handle was closed while waiting"));
        }
        for (ClusterSubscription subscription : List.copyOf(subscriptions)) {
            subscription.endedBy(robotworld.space.SubscriptionEnd.SPACE_CLOSED);
        }
    }

    private void checkOpen() {
        if (closed) {
            throw new SpaceClosedException("the space handle is closed");
        }
        if (node.isClosed()) {
            throw ClusterNode.memberGone(uri);
        }
    }

    private String resolve(ContainerRef container) {
        Objects.requireNonNull(container, "container");
        checkOpen();
        if (!uri.equals(container.space())) {
            throw new ContainerNotFoundException(container + " belongs to another space than " + uri);
        }
        return container.id();
    }

    private ContainerRef ref(String id) {
        return new ContainerRef(uri, id);
    }

    /** The deadline of a call that does not wait in its container: now plus the network allowance. */
    private long allowance() {
        return ClusterNode.deadlineIn(node.options().callAllowance().toMillis());
    }

    @Override
    public String toString() {
        return "ClusterSpace[" + uri + " via " + node.self() + "]";
    }
}
