package robotworld.space;

import java.net.URI;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * The core API of a space: containers with a naming service, the five operations on entries, and
 * notifications. Implemented in-process by {@link EmbeddedSpace} and over HTTP by the remote client; both
 * behave the same (one contract test suite runs against both).
 *
 * <p><b>Blocking.</b> {@code read}, {@code take} and {@code destroy} wait until their selectors find enough
 * entries; {@code write} waits while the container is full, a key or vector position it needs is occupied, or
 * (SET) an equal entry is present; {@code shift} never waits, it displaces instead. Each operation waits at most
 * its {@link Timeout} and then throws {@link SpaceTimeoutException}. Waiting operations are served oldest first.
 *
 * <p><b>Atomicity.</b> Each operation on a container is atomic and linearizable: all of its entries are
 * selected or placed in one step, and concurrent operations behave as if run one after another.
 *
 * <p><b>Failures</b> are {@link SpaceException}s: {@link SpaceTimeoutException},
 * {@link ContainerNotFoundException} (its subclass {@link ContainerDestroyedException} for operations that were
 * waiting when the container was destroyed), {@link ContainerNameTakenException},
 * {@link InvalidOperationException}, {@link SpaceClosedException} and {@link SpaceInterruptedException}.
 */
public interface Capi extends AutoCloseable {

    /**
     * The URI naming this space; every {@link ContainerRef} it hands out carries it.
     *
     * @return the space's URI
     */
    URI spaceUri();

    // ---- naming service ----

    /**
     * Creates a container. A named one is registered with the naming service.
     *
     * @param spec how the container behaves, and its name (null for an anonymous container)
     * @return a reference to the new container
     * @throws ContainerNameTakenException if the name is in use
     */
    ContainerRef createContainer(ContainerSpec spec);

    /**
     * Finds a named container.
     *
     * @param name the container's name
     * @return the container registered under {@code name}
     * @throws ContainerNotFoundException if there is none
     */
    ContainerRef lookupContainer(String name);

    /**
     * The container named by {@code spec.name()}, created from {@code spec} if it does not exist yet; atomic, so
     * participants racing to set up the same container all get the same one.
     *
     * @param spec the wanted container, with a name
     * @return the existing or new container
     * @throws IllegalArgumentException    if {@code spec} has no name
     * @throws ContainerNameTakenException if the existing container has a different spec
     */
    ContainerRef lookupOrCreateContainer(ContainerSpec spec);

    /**
     * Destroys a container and its entries, frees its name, fails every operation waiting on it with
     * {@link ContainerDestroyedException} and ends its subscriptions.
     *
     * @param container the container
     * @throws ContainerNotFoundException if it does not exist
     */
    void destroyContainer(ContainerRef container);

    /**
     * A snapshot of a container's spec and state.
     *
     * @param container the container
     * @return its spec, size, blocked operations and subscriptions
     * @throws ContainerNotFoundException if it does not exist
     */
    ContainerInfo describeContainer(ContainerRef container);

    // ---- operations ----

    /**
     * Returns the selected entries and leaves them in place; counts as use for LRU.
     *
     * @param container the container
     * @param timeout   how long to wait for enough entries
     * @param selectors a selector chain; none means one entry in the base order
     * @return the entries, in the order the (last) selector gives
     * @throws SpaceTimeoutException      if not enough entries came in time
     * @throws InvalidOperationException  if the selectors can never be satisfied on this container
     * @throws ContainerNotFoundException if the container does not exist or is destroyed while waiting
     */
    List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors);

    /**
     * Removes the selected entries and returns them; as {@link #read} otherwise.
     *
     * @param container the container
     * @param timeout   how long to wait for enough entries
     * @param selectors a selector chain; none means one entry in the base order
     * @return the removed entries
     * @throws SpaceTimeoutException      if not enough entries came in time
     * @throws InvalidOperationException  if the selectors can never be satisfied on this container
     * @throws ContainerNotFoundException if the container does not exist or is destroyed while waiting
     */
    List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors);

    /**
     * Removes the selected entries without returning them; as {@link #take} otherwise.
     *
     * @param container the container
     * @param timeout   how long to wait for enough entries
     * @param selectors a selector chain; none means one entry in the base order
     * @return how many entries were removed
     * @throws SpaceTimeoutException      if not enough entries came in time
     * @throws InvalidOperationException  if the selectors can never be satisfied on this container
     * @throws ContainerNotFoundException if the container does not exist or is destroyed while waiting
     */
    int destroy(ContainerRef container, Timeout timeout, Selector... selectors);

    /**
     * Writes all items at once, waiting while they do not all fit: not enough room, a key or vector position
     * taken, or (SET) an equal entry present.
     *
     * @param container the container
     * @param timeout   how long to wait for room
     * @param items     the entries with their keys and positions
     * @throws SpaceTimeoutException      if they did not fit in time
     * @throws InvalidOperationException  if they can never fit (more than the capacity, duplicate keys,
     *                                    positions or SET entries among them, a view the container lacks)
     * @throws ContainerNotFoundException if the container does not exist or is destroyed while waiting
     */
    void write(ContainerRef container, Timeout timeout, List<Item> items);

    /**
     * Writes the items one after another without ever waiting: the equal entry (SET), the entry under the same
     * key, the entry at the same vector position, and, when the container is full, the entry its base order
     * would take next, are pushed out to make room.
     *
     * @param container the container
     * @param timeout   bounds only the call itself (a remote call may wait for the network)
     * @param items     the entries with their keys and positions
     * @return the displaced entries, in the order they were pushed out
     * @throws InvalidOperationException  if an item uses a view the container lacks
     * @throws ContainerNotFoundException if the container does not exist
     */
    List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items);

    /**
     * Writes plain entries (no key, appended to a vector); see {@link #write(ContainerRef, Timeout, List)}.
     *
     * @param container the container
     * @param timeout   how long to wait for room
     * @param entries   the entries
     */
    default void write(ContainerRef container, Timeout timeout, Entry... entries) {
        write(container, timeout, items(entries));
    }

    /**
     * Shifts plain entries (no key, appended to a vector); see {@link #shift(ContainerRef, Timeout, List)}.
     *
     * @param container the container
     * @param timeout   bounds only the call itself
     * @param entries   the entries
     * @return the displaced entries
     */
    default List<Entry> shift(ContainerRef container, Timeout timeout, Entry... entries) {
        return shift(container, timeout, items(entries));
    }

    /**
     * Writes {@code items} into {@code writeTo}, then takes from {@code takeFrom}: the two operations one after the
     * other, within one timeout. It is the shape of a request/answer exchange (write the request, wait for its
     * answer), and a remote space sends it as one request, so the take is waiting on the server without a second
     * round trip. Each of the two operations is atomic as usual; the pair is not: other operations may come
     * between them, and the take's selectors may find anything that is there when it runs.
     *
     * @param writeTo   the container to write into
     * @param items     the entries to write, as for {@link #write(ContainerRef, Timeout, List)}
     * @param takeFrom  the container to take from (may be {@code writeTo})
     * @param timeout   bounds both: the write waits at most this long, the take at most what is left of it
     * @param selectors the take's selectors
     * @return the taken entries
     * @throws SpaceTimeoutException      if the write or the take could not happen in time; a failure of the take
     *                                    (this or any other) leaves the write done
     * @throws SpaceInterruptedException  if interrupted while waiting: the take had no effect, the write may have
     *                                    happened
     */
    default List<Entry> writeThenTake(ContainerRef writeTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                      Selector... selectors) {
        long start = System.nanoTime();
        write(writeTo, timeout, items);
        return take(takeFrom, Timeout.remaining(timeout, start), selectors);
    }

    /**
     * Shifts {@code items} into {@code shiftTo}, then takes from {@code takeFrom}: as
     * {@link #writeThenTake}, with a shift (which never waits) instead of the write. What the shift displaces is
     * not returned. A server answering requests uses it to deliver one answer and wait for the next request in one
     * exchange.
     *
     * @param shiftTo   the container to shift into
     * @param items     the entries to shift, as for {@link #shift(ContainerRef, Timeout, List)}
     * @param takeFrom  the container to take from (may be {@code shiftTo})
     * @param timeout   bounds both: the take waits at most what is left of it after the shift
     * @param selectors the take's selectors
     * @return the taken entries
     * @throws SpaceTimeoutException     if the take could not happen in time; a failure of the take (this or any
     *                                   other) leaves the shift done
     * @throws SpaceInterruptedException if interrupted while waiting: the take had no effect, the shift may have
     *                                   happened
     */
    default List<Entry> shiftThenTake(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                      Selector... selectors) {
        long start = System.nanoTime();
        shift(shiftTo, timeout, items);
        return take(takeFrom, Timeout.remaining(timeout, start), selectors);
    }

    // ---- notifications ----

    /**
     * Starts observing a container.
     *
     * @param container  the container
     * @param operations which operations to report ({@link Operation#any()} for all, including the container's
     *                   destruction)
     * @param mode       how long the subscription lasts, with {@code timeout}
     * @param timeout    see {@link NotificationMode}; ignored for {@link NotificationMode#INFINITE}
     * @param listener   receives the notifications, in operation order, on a thread of the space
     * @return a handle to cancel the subscription
     * @throws ContainerNotFoundException if the container does not exist
     */
    Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode, Timeout timeout,
                           NotificationListener listener);

    /**
     * Closes this space (or connection): operations still waiting fail with {@link SpaceClosedException} and
     * subscriptions end with {@link SubscriptionEnd#SPACE_CLOSED}. Idempotent.
     */
    @Override
    void close();

    private static List<Item> items(Entry... entries) {
        List<Item> items = new ArrayList<>(entries.length);
        for (Entry entry : entries) {
            items.add(Item.of(entry));
        }
        return items;
    }
}
