package robotworld.space;

import java.net.URI;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.UUID;

import robotworld.space.internal.ContainerRegistry;

/**
 * The space as an in-process engine. Each container has its own lock; operations on different containers never
 * contend. Close it when done to stop its notification threads (they are daemon threads, so a forgotten space
 * does not keep the JVM alive).
 *
 * <pre>{@code
 * try (Capi space = EmbeddedSpace.open()) {
 *     ContainerRef queue = space.createContainer(ContainerSpec.of(Order.FIFO).named("jobs"));
 *     space.write(queue, Timeout.TRY_ONCE, Tuple.of("host-a", 42));
 *     List<Entry> job = space.take(queue, Timeout.ofMillis(500));
 * }
 * }</pre>
 */
public final class EmbeddedSpace implements SpaceEngine, AsyncTakes {

    /** Undelivered notifications a subscription may queue before it ends as {@link SubscriptionEnd#OVERFLOWED}. */
    public static final int DEFAULT_NOTIFICATION_QUEUE = 10_000;

    private final URI uri;
    private final ContainerRegistry containers;

    private EmbeddedSpace(URI uri, int notificationQueueCapacity) {
        this.uri = Objects.requireNonNull(uri, "uri");
        this.containers = new ContainerRegistry(uri, notificationQueueCapacity);
    }

    /** A new, empty space with a unique {@code embedded:} URI and the default notification queue. */
    public static EmbeddedSpace open() {
        return open(DEFAULT_NOTIFICATION_QUEUE);
    }

    /** A new, empty space whose subscriptions may each queue {@code notificationQueueCapacity} notifications. */
    public static EmbeddedSpace open(int notificationQueueCapacity) {
        return open(URI.create("embedded:" + UUID.randomUUID()), notificationQueueCapacity);
    }

    /**
     * A new, empty space with the given URI, e.g. the public address of a server that exposes it, so that its
     * crefs are valid for remote clients too.
     */
    public static EmbeddedSpace open(URI uri, int notificationQueueCapacity) {
        return new EmbeddedSpace(uri, notificationQueueCapacity);
    }

    @Override
    public URI spaceUri() {
        return uri;
    }

    @Override
    public ContainerRef createContainer(ContainerSpec spec) {
        return containers.create(Objects.requireNonNull(spec, "spec")).ref();
    }

    @Override
    public ContainerRef lookupContainer(String name) {
        return containers.lookup(Objects.requireNonNull(name, "name")).ref();
    }

    @Override
    public ContainerRef lookupOrCreateContainer(ContainerSpec spec) {
        return containers.lookupOrCreate(Objects.requireNonNull(spec, "spec")).ref();
    }

    @Override
    public void destroyContainer(ContainerRef container) {
        containers.destroy(Objects.requireNonNull(container, "container"));
    }

    @Override
    public ContainerInfo describeContainer(ContainerRef container) {
        return containers.resolve(Objects.requireNonNull(container, "container")).info();
    }

    @Override
    public List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors) {
        return containers.resolve(container).retrieve(Operation.READ, Objects.requireNonNull(timeout, "timeout"),
                selectors);
    }

    @Override
    public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
        return containers.resolve(container).retrieve(Operation.TAKE, Objects.requireNonNull(timeout, "timeout"),
                selectors);
    }

    @Override
    public int destroy(ContainerRef container, Timeout timeout, Selector... selectors) {
        return containers.resolve(container).retrieve(Operation.DESTROY, Objects.requireNonNull(timeout, "timeout"),
                selectors).size();
    }

    @Override
    public void write(ContainerRef container, Timeout timeout, List<Item> items) {
        containers.resolve(container).write(Objects.requireNonNull(timeout, "timeout"), items);
    }

    @Override
    public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
        Objects.requireNonNull(timeout, "timeout"); // in-process, shift never waits
        return containers.resolve(container).shift(items);
    }

    @Override
    public Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode,
                                  Timeout timeout, NotificationListener listener) {
        Objects.requireNonNull(operations, "operations");
        Objects.requireNonNull(mode, "mode");
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(listener, "listener");
        return containers.resolve(container).subscribe(operations, mode, timeout, listener);
    }

    // ---- for servers that expose this space (SpaceEngine, not part of Capi) ----

    @Override
    public Removal removeWithReceipt(ContainerRef container, Operation operation, Timeout timeout,
                                     Selector... selectors) {
        return containers.resolve(container).removeWithReceipt(operation, Objects.requireNonNull(timeout, "timeout"),
                selectors);
    }

    @Override
    public long sequence(ContainerRef container) {
        return containers.resolve(Objects.requireNonNull(container, "container")).sequence();
    }

    @Override
    @SuppressWarnings("unchecked")
    public Pending readLater(ContainerRef container, Timeout timeout, Selector[] selectors,
                             Completion<List<Entry>> done) {
        Objects.requireNonNull(done, "done");
        return containers.resolve(container).retrieveLater(Operation.READ, Objects.requireNonNull(timeout, "timeout"),
                selectors, (Completion<Object>) (Completion<?>) done);
    }

    @Override
    @SuppressWarnings("unchecked")
    public Pending removeLater(ContainerRef container, Operation operation, Timeout timeout, Selector[] selectors,
                               Completion<Removal> done) {
        Objects.requireNonNull(done, "done");
        return containers.resolve(container).retrieveLater(operation, Objects.requireNonNull(timeout, "timeout"),
                selectors, (Completion<Object>) (Completion<?>) done);
    }

    @Override
    public Pending writeLater(ContainerRef container, Timeout timeout, List<Item> items, Completion<Void> done) {
        Objects.requireNonNull(done, "done");
        return containers.resolve(container).writeLater(Objects.requireNonNull(timeout, "timeout"), items,
                new Completion<>() {
                    @Override
                    public void completed(Object result) {
                        done.completed(null);
                    }

                    @Override
                    public void failed(SpaceException failure) {
                        done.failed(failure);
                    }
                });
    }

    @Override
    public Pending takeLater(ContainerRef container, Timeout timeout, Selector[] selectors,
                             Completion<List<Entry>> done) {
        Objects.requireNonNull(done, "done");
        return containers.resolve(container).retrieveLater(Operation.TAKE, Objects.requireNonNull(timeout, "timeout"),
                selectors, new Completion<>() {
                    @Override
                    public void completed(Object removal) {
                        done.completed(((Removal) removal).entries()); // in-process, a take needs no receipt
                    }

                    @Override
                    public void failed(SpaceException failure) {
                        done.failed(failure);
                    }
                });
    }

    @Override
    public Pending shiftThenTakeLater(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                      Selector[] selectors, Completion<List<Entry>> done) {
        shift(shiftTo, timeout, items);
        return takeLater(takeFrom, timeout, selectors, done);
    }

    @Override
    public void close() {
        containers.close();
    }

    @Override
    public String toString() {
        return "EmbeddedSpace[" + uri + "]";
    }
}
