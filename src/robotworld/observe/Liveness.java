package robotworld.observe;

import java.time.Instant;

/**
 * Whether a participant's program is running, as far as its heartbeats and its traffic tell (see the package
 * documentation).
 *
 * @param participant the robot or environment
 * @param state       what the tap concludes
 * @param lastSign    the last sign of life (a heartbeat arrived, a request taken, an answer published), or null if
 *                    none was seen
 * @param basis       what the conclusion rests on, in words (e.g. "heartbeats of robot-pc#q1w2", "a request has
 *                    waited 4 s")
 */
public record Liveness(String participant, State state, Instant lastSign, String basis) {

    /** What is known about a participant. */
    public enum State {
        /** The programs serving its modules send heartbeats, or (without heartbeats) its Local sides answered. */
        ALIVE,
        /** A program serving one of its modules sends no more heartbeats: killed, frozen or cut off from the space. */
        SILENT,
        /** The programs serving its modules have ended cleanly (their last heartbeats said so). */
        ENDED,
        /** A request to one of its modules has waited longer than the liveness window: nobody serves it. */
        NOT_ANSWERING,
        /** Quiet: no heartbeat names it and nothing was seen within the window, so nothing tells whether it runs. */
        UNKNOWN
    }
}
