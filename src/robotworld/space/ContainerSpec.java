package robotworld.space;

import java.util.Objects;

/**
 * How a container behaves: its optional name, capacity, uniqueness, base order and views. Immutable; build one
 * fluently, e.g. {@code ContainerSpec.of(Order.FIFO).named("REQUEST").bounded(100)}.
 *
 * @param name       unique name in the space, or {@code null} for an anonymous container reached only by cref
 * @param capacity   the most entries the container holds at once, or {@link #UNBOUNDED}
 * @param uniqueness BAG (duplicates allowed) or SET
 * @param order      the base order: how entries are chosen when no selector says otherwise
 * @param keyView    whether entries may be written under a unique key and selected by it
 * @param vectorView whether every entry has a vector position and can be selected by it
 */
public record ContainerSpec(String name, int capacity, Uniqueness uniqueness, Order order, boolean keyView,
                            boolean vectorView) {

    /** Capacity of a container that grows without limit. */
    public static final int UNBOUNDED = -1;

    /** Validates the fields. */
    public ContainerSpec {
        Objects.requireNonNull(uniqueness, "uniqueness");
        Objects.requireNonNull(order, "order");
        if (capacity < 1 && capacity != UNBOUNDED) {
            throw new IllegalArgumentException("capacity must be at least 1, or UNBOUNDED; was " + capacity);
        }
        if (name != null && name.isBlank()) {
            throw new IllegalArgumentException("a container name must not be blank");
        }
    }

    /** An anonymous, unbounded BAG with the thesis's default base order RANDOM and no views. */
    public static ContainerSpec defaults() {
        return new ContainerSpec(null, UNBOUNDED, Uniqueness.BAG, Order.RANDOM, false, false);
    }

    /** An anonymous, unbounded BAG with base order {@code order} and no views. */
    public static ContainerSpec of(Order order) {
        return defaults().ordered(order);
    }

    /** This spec with the given name. */
    public ContainerSpec named(String newName) {
        return new ContainerSpec(newName, capacity, uniqueness, order, keyView, vectorView);
    }

    /** This spec without a name (an anonymous container). */
    public ContainerSpec anonymous() {
        return new ContainerSpec(null, capacity, uniqueness, order, keyView, vectorView);
    }

    /** This spec holding at most {@code newCapacity} entries. */
    public ContainerSpec bounded(int newCapacity) {
        return new ContainerSpec(name, newCapacity, uniqueness, order, keyView, vectorView);
    }

    /** This spec without a capacity limit. */
    public ContainerSpec unbounded() {
        return new ContainerSpec(name, UNBOUNDED, uniqueness, order, keyView, vectorView);
    }

    /** This spec with uniqueness SET. */
    public ContainerSpec set() {
        return new ContainerSpec(name, capacity, Uniqueness.SET, order, keyView, vectorView);
    }

    /** This spec with uniqueness BAG. */
    public ContainerSpec bag() {
        return new ContainerSpec(name, capacity, Uniqueness.BAG, order, keyView, vectorView);
    }

    /** This spec with base order {@code newOrder}. */
    public ContainerSpec ordered(Order newOrder) {
        return new ContainerSpec(name, capacity, uniqueness, newOrder, keyView, vectorView);
    }

    /** This spec with a KEY view. */
    public ContainerSpec withKeyView() {
        return new ContainerSpec(name, capacity, uniqueness, order, true, vectorView);
    }

    /** This spec with a VECTOR view. */
    public ContainerSpec withVectorView() {
        return new ContainerSpec(name, capacity, uniqueness, order, keyView, true);
    }

    /** Whether the capacity is limited. */
    public boolean isBounded() {
        return capacity != UNBOUNDED;
    }
}
