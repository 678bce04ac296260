package robotworld.space;

/**
 * A snapshot of a container's state, for monitoring and tests.
 *
 * @param ref           the container
 * @param spec          how it was created (including its name, if any)
 * @param size          entries it holds
 * @param blocked       operations currently waiting on it (blocked reads, takes, destroys and writes)
 * @param subscriptions active notification subscriptions on it
 */
public record ContainerInfo(ContainerRef ref, ContainerSpec spec, int size, int blocked, int subscriptions) {
}
