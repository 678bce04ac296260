package robotworld.observe;

import java.time.Instant;

/**
 * Whether a participant's program is running, as far as its traffic tells (see the package documentation).
 *
 * @param participant the robot or environment
 * @param state       what the tap concludes
 * @param lastSign    the last sign of life (a request taken, an answer published), or null if none was seen
 * @param basis       what the conclusion rests on, in words (e.g. "answers", "a request waits 4 s")
 */
public record Liveness(String participant, State state, Instant lastSign, String basis) {

    /** What is known about a participant. */
    public enum State {
        /** Its Local sides took requests or published answers within the liveness window. */
        ALIVE,
        /** A request to one of its modules has waited longer than the liveness window: nobody serves it. */
        NOT_ANSWERING,
        /** Quiet: nothing seen within the window, so nothing tells whether it runs. */
        UNKNOWN
    }
}
