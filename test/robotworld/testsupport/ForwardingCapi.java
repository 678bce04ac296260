package robotworld.testsupport;

import java.net.URI;
import java.util.List;
import java.util.Set;

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

/** A {@link Capi} that passes every call to another; test set-ups extend it to add what closing must also end. */
public abstract class ForwardingCapi implements Capi {

    protected final Capi delegate;

    protected ForwardingCapi(Capi delegate) {
        this.delegate = delegate;
    }

    @Override
    public URI spaceUri() {
        return delegate.spaceUri();
    }

    @Override
    public ContainerRef createContainer(ContainerSpec spec) {
        return delegate.createContainer(spec);
    }

    @Override
    public ContainerRef lookupContainer(String name) {
        return delegate.lookupContainer(name);
    }

    @Override
    public ContainerRef lookupOrCreateContainer(ContainerSpec spec) {
        return delegate.lookupOrCreateContainer(spec);
    }

    @Override
    public void destroyContainer(ContainerRef container) {
        delegate.destroyContainer(container);
    }

    @Override
    public ContainerInfo describeContainer(ContainerRef container) {
        return delegate.describeContainer(container);
    }

    @Override
    public List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors) {
        return delegate.read(container, timeout, selectors);
    }

    @Override
    public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
        return delegate.take(container, timeout, selectors);
    }

    @Override
    public int destroy(ContainerRef container, Timeout timeout, Selector... selectors) {
        return delegate.destroy(container, timeout, selectors);
    }

    @Override
    public void write(ContainerRef container, Timeout timeout, List<Item> items) {
        delegate.write(container, timeout, items);
    }

    @Override
    public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
        return delegate.shift(container, timeout, items);
    }

    @Override
    public Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode,
                                  Timeout timeout, NotificationListener listener) {
        return delegate.subscribe(container, operations, mode, timeout, listener);
    }

    @Override
    public void close() {
        delegate.close();
    }
}
