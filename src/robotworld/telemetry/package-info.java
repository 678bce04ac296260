/**
 * A world's traffic as timestamped JSON messages on named topics, each topic with a JSON Schema: the one
 * vocabulary shared by the recorder (MCAP files) and the Foxglove WebSocket endpoint, so a layout made for the
 * live view works for a recording too, and a recording can be replayed into a space.
 *
 * <h2>The contract</h2>
 * <ul>
 *   <li>{@link robotworld.telemetry.WorldTelemetry} is a {@link robotworld.observe.WorldObserver}: it turns each
 *       event of a {@link robotworld.observe.WorldTap} into one or more {@link robotworld.telemetry.TelemetryMessage}s
 *       and hands them to a sink, on the tap's thread, in the tap's order.</li>
 *   <li>Topics ({@link robotworld.telemetry.Topics}): {@code /<Participant>/<Module>} per module (schema
 *       {@code rwe.ModuleTraffic}: requests, answers and error answers with the exact tuple), {@code /rwe/liveness},
 *       {@code /rwe/stops}, {@code /rwe/gaps}; per simulated robot {@code /<Robot>/ground_truth}
 *       ({@code rwe.GroundTruth}), {@code /<Robot>/scene} ({@code foxglove.SceneUpdate}), {@code /<Robot>/pose}
 *       ({@code foxglove.PoseInFrame}), {@code /<Robot>/ir/<address>.<sensor>} ({@code foxglove.LaserScan}), and
 *       {@code /tf} ({@code foxglove.FrameTransforms}: frame {@code arena}, child frame per robot). The
 *       {@code foxglove.*} schemas carry the fields this program fills of the well-known Foxglove schemas of the same
 *       name; lengths there are metres, angles radians.</li>
 *   <li>A message's time is when the observer saw the event (a ground-truth frame: when the simulator took it),
 *       in nanoseconds since the epoch.</li>
 *   <li>{@link robotworld.telemetry.TrafficJson} reads {@code rwe.ModuleTraffic} and {@code rwe.GroundTruth}
 *       messages back into tuples and frames, exactly (integers stay 64-bit), for replay.</li>
 * </ul>
 * The schemas are in this package's {@code schemas/} folder and documented for users in {@code docs/recording.md}.
 */
package robotworld.telemetry;
