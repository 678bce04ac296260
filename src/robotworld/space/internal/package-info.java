/**
 * The engine behind {@link robotworld.space.EmbeddedSpace}: per-container stores, selection, placement, blocking
 * and notification delivery. Not an API: only {@code robotworld.space} uses it, and the clustered space
 * ({@code robotworld.cluster}) shares the container contents ({@link robotworld.space.internal.ContainerContents})
 * and the subscription delivery.
 */
package robotworld.space.internal;
