package robotworld.cluster;

import java.net.URI;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;

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
import robotworld.space.Subscription;
import robotworld.space.Timeout;

/**
 * One space seen through handles on several members, as one {@link Capi}: every call goes to the next member in
 * turn, so consecutive calls of one thread, and the threads of a test, use different members. A blocked take on
 * one member is then served by a write on another, a subscription on one sees the writes of all.
 */
final class RotatingCapi implements Capi {

    private final List<? extends Capi> handles;
    private final AtomicInteger next = new AtomicInteger();

    RotatingCapi(List<? extends Capi> handles) {
        this.handles = List.copyOf(handles);
    }

    private Capi next() {
        return handles.get(Math.floorMod(next.getAndIncrement(), handles.size()));
    }

    @Override
    public URI spaceUri() {
        return handles.get(0).spaceUri();
    }

    @Override
    public ContainerRef createContainer(ContainerSpec spec) {
        return next().createContainer(spec);
    }

    @Override
    public ContainerRef lookupContainer(String name) {
        return next().lookupContainer(name);
    }

    @Override
    public ContainerRef lookupOrCreateContainer(ContainerSpec spec) {
        return next().lookupOrCreateContainer(spec);
    }

    @Override
    public void destroyContainer(ContainerRef container) {
        next().destroyContainer(container);
    }

    @Override
    public ContainerInfo describeContainer(ContainerRef container) {
        return next().describeContainer(container);
    }

    @Override
    public List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors) {
        return next().read(container, timeout, selectors);
    }

    @Override
    public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
        return next().take(container, timeout, selectors);
    }

    @Override
    public int destroy(ContainerRef container, Timeout timeout, Selector... selectors) {
        return next().destroy(container, timeout, selectors);
    }

    @Override
    public void write(ContainerRef container, Timeout timeout, List<Item> items) {
        next().write(container, timeout, items);
    }

    @Override
    public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
        return next().shift(container, timeout, items);
    }

    @Override
    public Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode,
                                  Timeout timeout, NotificationListener listener) {
        return next().subscribe(container, operations, mode, timeout, listener);
    }

    @Override
    public void close() {
        for (Capi handle : handles) {
            handle.close();
        }
    }
}
