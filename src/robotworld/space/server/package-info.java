/**
 * The space over HTTP: {@link robotworld.space.server.SpaceServer} serves an
 * {@link robotworld.space.EmbeddedSpace} with an embedded Jetty servlet (start it in any JVM, or with
 * {@code rwe space}). See {@code docs/wire.md} for the protocol, limits and restart behaviour.
 */
package robotworld.space.server;
