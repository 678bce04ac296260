/**
 * The wire format shared by server and client: typed JSON for entries, templates, selectors, items and specs, and a
 * compact binary form of the hot operations' bodies beside it ({@link robotworld.space.wire.BinaryWire}), both read
 * and written through {@link robotworld.space.wire.WireReader} and {@link robotworld.space.wire.WireWriter} (a reader
 * tells the two apart by a body's first byte); the framing of operations on upgraded connections
 * ({@link robotworld.space.wire.Frames}); the limits every message is checked against
 * ({@link robotworld.space.wire.WireLimits}) and the error kinds ({@link robotworld.space.wire.WireError}).
 * Described in {@code docs/wire.md}.
 */
package robotworld.space.wire;
