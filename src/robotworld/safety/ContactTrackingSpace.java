package robotworld.safety;

import java.net.URI;
import java.util.List;
import java.util.Set;
import java.util.function.Supplier;
import robotworld.space.AsyncTakes;
import robotworld.space.Capi;
import robotworld.space.ContainerInfo;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.Subscription;
import robotworld.space.Timeout;

/**
 * A space connection that tells the program's safety layer whenever the space answered: every operation that
 * returns, or fails with an answer of the space (a timeout, a container that is gone, a refused request), proves
 * that the space is reachable, so a busy program never looks cut off just because its heartbeat was slow. Failures
 * without an answer ({@link SpaceUnavailableException}, closed, interrupted) prove nothing. Otherwise it passes
 * every call through unchanged.
 */
final class ContactTrackingSpace implements Capi, AsyncTakes {

    private final Capi space;
    private final AsyncTakes takes;
    private final Runnable contact;

    ContactTrackingSpace(Capi space, Runnable contact) {
        this.space = space;
        this.takes = AsyncTakes.of(space);
        this.contact = contact;
    }

    private <T> T answered(Supplier<T> operation) {
        try {
            T result = operation.get();
            contact.run();
            return result;
        } catch (SpaceUnavailableException | SpaceClosedException | SpaceInterruptedException noAnswer) {
            throw noAnswer;
        } catch (SpaceException answer) {
            contact.run();
            throw answer;
        }
    }

    @Override
    public URI spaceUri() {
        return space.spaceUri();
    }

    @Override
    public ContainerRef createContainer(ContainerSpec spec) {
        return answered(() -> space.createContainer(spec));
    }

    @Override
    public ContainerRef lookupContainer(String name) {
        return answered(() -> space.lookupContainer(name));
    }

    @Override
    public ContainerRef lookupOrCreateContainer(ContainerSpec spec) {
        return answered(() -> space.lookupOrCreateContainer(spec));
    }

    @Override
    public void destroyContainer(ContainerRef container) {
        answered(() -> {
            space.destroyContainer(container);
            return null;
        });
    }

    @Override
    public ContainerInfo describeContainer(ContainerRef container) {
        return answered(() -> space.describeContainer(container));
    }

    @Override
    public List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors) {
        return answered(() -> space.read(container, timeout, selectors));
    }

    @Override
    public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
        return answered(() -> space.take(container, timeout, selectors));
    }

    @Override
    public int destroy(ContainerRef container, Timeout timeout, Selector... selectors) {
        return answered(() -> space.destroy(container, timeout, selectors));
    }

    @Override
    public void write(ContainerRef container, Timeout timeout, List<Item> items) {
        answered(() -> {
            space.write(container, timeout, items);
            return null;
        });
    }

    @Override
    public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
        return answered(() -> space.shift(container, timeout, items));
    }

    @Override
    public List<Entry> writeThenTake(ContainerRef writeTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                     Selector... selectors) {
        return answered(() -> space.writeThenTake(writeTo, items, takeFrom, timeout, selectors));
    }

    @Override
    public List<Entry> shiftThenTake(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom, Timeout timeout,
                                     Selector... selectors) {
        return answered(() -> space.shiftThenTake(shiftTo, items, takeFrom, timeout, selectors));
    }

    @Override
    public Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode,
                                  Timeout timeout, NotificationListener listener) {
        return answered(() -> space.subscribe(container, operations, mode, timeout, listener));
    }

    @Override
    public void close() {
        space.close();
    }

    @Override
    public String toString() {
        return space.toString();
    }

    // ---- takes that wait without a thread (how Local sides wait for requests) ----

    @Override
    public SpaceEngine.Pending takeLater(ContainerRef container, Timeout timeout, Selector[] selectors,
                                         SpaceEngine.Completion<List<Entry>> done) {
        return takes.takeLater(container, timeout, selectors, tracked(done));
    }

    @Override
    public SpaceEngine.Pending shiftThenTakeLater(ContainerRef shiftTo, List<Item> items, ContainerRef takeFrom,
                                                  Timeout timeout, Selector[] selectors,
                                                  SpaceEngine.Completion<List<Entry>> done) {
        return takes.shiftThenTakeLater(shiftTo, items, takeFrom, timeout, selectors, tracked(done));
    }

    /** The same completion, telling of the contact first when the space answered. */
    private SpaceEngine.Completion<List<Entry>> tracked(SpaceEngine.Completion<List<Entry>> done) {
        return new SpaceEngine.Completion<>() {
            @Override
            public void completed(List<Entry> entries) {
                contact.run();
                done.completed(entries);
            }

            @Override
            public void failed(SpaceException failure) {
                if (!(failure instanceof SpaceUnavailableException || failure instanceof SpaceClosedException
                        || failure instanceof SpaceInterruptedException)) {
                    contact.run();
                }
                done.failed(failure);
            }
        };
    }
}
