/**
 * The wire format shared by server and client: typed JSON for entries, templates, selectors, items and specs
 * ({@link robotworld.space.wire.WireReader}, {@link robotworld.space.wire.WireWriter}), the limits every message is
 * checked against ({@link robotworld.space.wire.WireLimits}) and the error kinds
 * ({@link robotworld.space.wire.WireError}). Described in {@code docs/wire.md}.
 */
package robotworld.space.wire;
