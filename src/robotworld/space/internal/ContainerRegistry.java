package robotworld.space.internal;

import java.net.URI;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

import robotworld.space.ContainerNameTakenException;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.SpaceClosedException;

/**
 * The containers of one space and the naming service. Lookups by id or name are lock-free (data operations
 * never contend here); creating and destroying containers, which are rare, are serialised.
 */
public final class ContainerRegistry {

    private final URI space;
    private final int queueCapacity;
    private final Delivery delivery;
    private final Map<String, ContainerEngine> byId = new ConcurrentHashMap<>();
    private final Map<String, ContainerEngine> byName = new ConcurrentHashMap<>();
    private final AtomicLong lastId = new AtomicLong();
    /**
     * Distinguishes this space instance's ids from those of any other, including a fresh space that replaced this
     * one after a restart: a cref kept across the restart then fails with ContainerNotFoundException instead of
     * silently naming a newer container that happens to have the same number.
     */
    private final String instanceTag = Long.toString(new java.security.SecureRandom().nextLong() >>> 16, 36);
    private volatile boolean closed;

    /**
     * @param space         URI stamped on every cref
     * @param queueCapacity undelivered notifications each subscription may queue before it overflows
     */
    public ContainerRegistry(URI space, int queueCapacity) {
        if (queueCapacity < 1) {
            throw new IllegalArgumentException("notification queue capacity must be at least 1");
        }
        this.space = space;
        this.queueCapacity = queueCapacity;
        this.delivery = new Delivery("space-" + Integer.toHexString(space.hashCode()));
    }

    public synchronized ContainerEngine create(ContainerSpec spec) {
        failIfClosed();
        if (spec.name() != null && byName.containsKey(spec.name())) {
            throw new ContainerNameTakenException("a container named '" + spec.name() + "' exists");
        }
        // ids are never reused, so a cref to a destroyed container never reaches a newer one
        ContainerRef ref = new ContainerRef(space, "c" + lastId.incrementAndGet() + "-" + instanceTag);
        ContainerEngine engine = new ContainerEngine(ref, spec, delivery, queueCapacity);
        byId.put(ref.id(), engine);
        if (spec.name() != null) {
            byName.put(spec.name(), engine);
        }
        return engine;
    }

    public synchronized ContainerEngine lookupOrCreate(ContainerSpec spec) {
        if (spec.name() == null) {
            throw new IllegalArgumentException("lookup-or-create needs a named spec");
        }
        failIfClosed();
        ContainerEngine existing = byName.get(spec.name());
        if (existing == null) {
            return create(spec);
        }
        if (!existing.spec().equals(spec)) {
            throw new ContainerNameTakenException("container '" + spec.name() + "' exists with a different spec: "
                    + existing.spec());
        }
        return existing;
    }

    public ContainerEngine lookup(String name) {
        failIfClosed();
        ContainerEngine engine = byName.get(name);
        if (engine == null) {
            throw new ContainerNotFoundException("no container named '" + name + "'");
        }
        return engine;
    }

    /** The container a cref points to. */
    public ContainerEngine resolve(ContainerRef ref) {
        failIfClosed();
        if (ref.space() != space && !ref.space().equals(space)) {
            throw new ContainerNotFoundException(ref + " belongs to another space than " + space);
        }
        ContainerEngine engine = byId.get(ref.id());
        if (engine == null) {
            throw new ContainerNotFoundException("no container " + ref + " (destroyed, or never created)");
        }
        return engine;
    }

    public void destroy(ContainerRef ref) {
        ContainerEngine engine;
        synchronized (this) {
            engine = resolve(ref);
            byId.remove(ref.id());
            if (engine.spec().name() != null) {
                byName.remove(engine.spec().name(), engine);
            }
        }
        engine.destroy(); // outside the registry lock: it takes the container's lock
    }

    /** Closes every container and stops the notification threads once their final signals are queued. */
    public void close() {
        List<ContainerEngine> engines;
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            engines = List.copyOf(byId.values());
            byId.clear();
            byName.clear();
        }
        for (ContainerEngine engine : engines) {
            engine.close();
        }
        delivery.close();
    }

    private void failIfClosed() {
        if (closed) {
            throw new SpaceClosedException("the space " + space + " is closed");
        }
    }
}
