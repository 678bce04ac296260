/**
 * Keeping a world's runs: recording its traffic into an MCAP file, and replaying such a file into a space so that
 * every view shows the run again.
 *
 * <h2>The contract</h2>
 * <ul>
 *   <li>{@link robotworld.recording.Recorder} is fed by a {@link robotworld.observe.WorldTap} (through
 *       {@link robotworld.recording.Recorder#observer()}) and writes every event as the JSON messages of
 *       {@link robotworld.telemetry} into an MCAP file (JSON encoding, JSON Schemas, chunked, indexed, with a
 *       summary). It never slows the tap: events wait in a bounded queue for the recorder's own writing thread;
 *       when the queue is full they are dropped <em>and counted</em>, and the count is written into the file (as a
 *       {@code /rwe/gaps} message and in the closing metadata) and shown by {@link Recorder#status()}. The file is
 *       flushed every second, so a killed recorder loses at most that; {@link Recorder#close()} finishes it.</li>
 *   <li>A recording also carries the world: its layout ({@value RecordingFormat#LAYOUT_ATTACHMENT}) and, when
 *       known, its description ({@value RecordingFormat#WORLD_ATTACHMENT}), and metadata records
 *       {@value RecordingFormat#START_METADATA} and {@value RecordingFormat#END_METADATA}.</li>
 *   <li>{@link robotworld.recording.Replayer} plays a recording's {@code rwe.ModuleTraffic} and
 *       {@code rwe.GroundTruth} messages into a space (requests written to REQUEST containers, answers and frames
 *       shifted into ANSWER and GROUNDTRUTH containers, as the live programs did), keeping the recorded pace at
 *       any rate, after putting a {@link robotworld.observe.ReplayMark} into the space. It never takes part in a
 *       world: nothing in a replay serves requests, so no hardware moves. Files written by other programs replay
 *       too if they carry messages of those schemas.</li>
 * </ul>
 * The file layout for users: {@code docs/recording.md}.
 */
package robotworld.recording;
