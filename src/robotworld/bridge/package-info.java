/**
 * A Foxglove WebSocket endpoint (protocol {@code foxglove.websocket.v1}) for a world: Foxglove or Lichtblick
 * connect to it and see the world's traffic live, on the topics of {@link robotworld.telemetry}, with no code.
 *
 * <h2>The contract</h2>
 * <ul>
 *   <li>{@link robotworld.bridge.FoxgloveBridge} serves the protocol on its own Jetty server (Jetty's WebSocket
 *       support), fed by a {@link robotworld.observe.WorldTap} through {@link robotworld.bridge.FoxgloveBridge#observer()}.
 *       It sends Server Info on connect, advertises one channel per topic (JSON encoding, JSON Schema) at once and
 *       each new topic when it first appears, and sends Message Data to the subscribers of a channel, in the order
 *       the tap delivered the events. A client that subscribes is first sent the channel's latest message, so it
 *       sees the current state without waiting.</li>
 *   <li>It only shows: it offers no client publishing, services or parameters, so nothing reaches the world.</li>
 *   <li>Loopback by default; with a token, a client must send it as {@code Authorization: Bearer <token>} or, since
 *       browsers cannot set headers on a WebSocket, as the query parameter {@code ?token=...}. At most
 *       {@link robotworld.bridge.FoxgloveBridge.Options#maxClients()} connections; a request that is no WebSocket
 *       upgrade, offers no {@code foxglove.websocket.v1}, lacks the token or exceeds the limit gets a 4xx/503 answer.</li>
 *   <li>A slow client never slows the world: each has a bounded backlog; messages beyond it are dropped for that
 *       client, counted, and reported to it as a warning Status message.</li>
 *   <li>A replay (see {@link robotworld.observe.ReplayMark}) is said in the server's name, its metadata and a Status
 *       message to every client.</li>
 * </ul>
 */
package robotworld.bridge;
