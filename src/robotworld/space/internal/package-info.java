/**
 * The engine behind {@link robotworld.space.EmbeddedSpace}: per-container stores, selection, placement, blocking
 * and notification delivery. Not an API: only {@code robotworld.space} uses it.
 */
package robotworld.space.internal;
