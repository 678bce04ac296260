/**
 * The space over HTTP: {@link robotworld.space.server.SpaceServer} serves a {@link robotworld.space.SpaceEngine}
 * (the in-process {@link robotworld.space.EmbeddedSpace} by default) with an embedded Jetty: operations through a
 * core handler that never blocks ({@code OperationsHandler}: a waiting operation is an object in the engine,
 * answered by the thread that completes it), the server description and the notification streams through a
 * servlet. The engine is reached only through {@code SpaceEngine}, so another engine plugs into the same server
 * with the same waiting. Start it in any JVM, or with {@code rwe space}. See {@code docs/wire.md} for the
 * protocol, limits and restart behaviour.
 */
package robotworld.space.server;
