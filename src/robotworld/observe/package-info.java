/**
 * Watching a running world's traffic without taking part in it: one small observer interface for everything that
 * shows, records or forwards what happens in a RobotWorld (the monitor window, the console monitor, a recorder, a
 * bridge to other tools), and the one tap that reads a world's containers in a space and hands the events to the
 * observers.
 *
 * <h2>The contract</h2>
 * <ul>
 *   <li>A {@link robotworld.observe.WorldTap} subscribes to the containers of the modules of one world
 *       ({@code <Participant><Module>REQUEST} and {@code ...ANSWER}, see the runtime's documentation), to each
 *       robot's ground-truth container ({@code <Participant>GROUNDTRUTH}, written by a simulator) and to the
 *       programs' heartbeats ({@code rwe.liveness}). It only reads: it never slows down or changes a control
 *       program.</li>
 *   <li>Every {@link robotworld.observe.WorldObserver} method is called on the tap's <em>one</em> dispatch thread,
 *       one call at a time, in the order the tap received the events. An observer therefore needs no locking for
 *       its own state, but must return quickly and must not block (hand slow work to a thread of its own, or to
 *       the Swing event thread). An exception thrown by an observer is logged and does not stop the tap or the
 *       other observers.</li>
 *   <li>Events may be missing, and the tap says so: when the space dropped notifications (a subscription
 *       overflowed or its container was destroyed and watching resumed), when observers fell so far behind that
 *       the tap's bounded queue was full, and when watching ended (the space connection closed),
 *       {@link robotworld.observe.WorldObserver#gap} is called. Without a gap signal, every request and answer
 *       the space reported has been delivered. An answer that arrives between the tap's first read of a container
 *       and its subscription can be missed without a gap; the next one brings observers up to date.</li>
 *   <li>Events carry the time the tap received them. A call's latency is the time between the tap seeing its
 *       request written and its answer arriving, so it is known only for remote calls (a local call on the
 *       module's own computer is published after it happened, without its duration), and only when the tap heard
 *       of the request first: the space delivers each container's notifications on a thread of its own, so now
 *       and then an answer overtakes its request, and then its latency is unknown.</li>
 *   <li>Liveness rests on the heartbeats every program shifts into {@code rwe.liveness} (see
 *       {@link robotworld.safety.Heartbeat}), judged with this computer's clock. A participant is
 *       {@link robotworld.observe.Liveness.State#ALIVE} while the programs serving its modules send heartbeats,
 *       idle or not; {@link robotworld.observe.Liveness.State#SILENT} once one of them has sent none for a second
 *       (five heartbeat periods, if longer): killed, frozen or cut off from the space; and
 *       {@link robotworld.observe.Liveness.State#ENDED} when their last heartbeats said they ended. A request to
 *       one of its modules that has waited longer than the liveness window makes it
 *       {@link robotworld.observe.Liveness.State#NOT_ANSWERING} (the program runs, but nobody takes the request).
 *       Where no heartbeat names a participant (programs with heartbeats switched off), its traffic tells:
 *       alive while its Local sides take requests or publish answers, and
 *       {@link robotworld.observe.Liveness.State#UNKNOWN} while it is quiet. The tap reports each change, as it
 *       reports each change of a module's queue length.</li>
 *   <li>Replays: a space into which {@code rwe replay} plays a recording holds a {@link robotworld.observe.ReplayMark};
 *       the tap hands it to {@link robotworld.observe.WorldObserver#replay} before any event, and every view
 *       marks what it shows as a replay.</li>
 * </ul>
 *
 * <p>This package does not depend on Swing or on description files: a world is given as a
 * {@link robotworld.observe.WorldLayout}.
 */
package robotworld.observe;
