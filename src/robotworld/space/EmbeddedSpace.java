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
public final class EmbeddedSpace implements Capi {

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

    // ---- for servers that expose this space (not part of Capi) ----

    /**
     * A {@link #take} (or, with {@link Operation#DESTROY}, a {@link #destroy}) whose effect can be undone with
     * {@link Removal#restore()}. A server uses it to acknowledge before losing: it keeps the removal until the
     * client confirms receipt and restores the entries if the confirmation never comes.
     *
     * @param container the container
     * @param operation {@link Operation#TAKE} or {@link Operation#DESTROY}
     * @param timeout   how long to wait for enough entries
     * @param selectors a selector chain; none means one entry in the base order
     * @return the removal, already done
     */
    public Removal removeWithReceipt(ContainerRef container, Operation operation, Timeout timeout,
                                     Selector... selectors) {
        return containers.resolve(container).removeWithReceipt(operation, Objects.requireNonNull(timeout, "timeout"),
                selectors);
    }

    /**
     * The sequence number of the latest operation on a container, as carried by {@link Notification#sequence()}.
     * A remote client compares it across a reconnection to learn whether it missed operations.
     *
     * @param container the container
     * @return the latest sequence number (0 before the first operation)
     * @throws ContainerNotFoundException if the container does not exist
     */
    public long sequence(ContainerRef container) {
        return containers.resolve(Objects.requireNonNull(container, "container")).sequence();
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
