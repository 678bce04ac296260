package robotworld.observe;

/**
 * Watches a world's traffic through a {@link WorldTap}. Every method has an empty default, so an observer
 * implements only what it needs. Calls come from the tap's one dispatch thread, one at a time, in order; return
 * quickly and never block (see the package documentation for the whole contract).
 */
public interface WorldObserver {

    /** A request was written for a module (a remote call on its way). */
    default void requestSeen(RequestSeen event) {
    }

    /** The number of requests waiting for a module changed. */
    default void queueLength(QueueLength event) {
    }

    /** An answer or error answer arrived (a served remote call or a published local call). */
    default void answerSeen(AnswerSeen event) {
    }

    /** What is known about a participant's program changed. */
    default void liveness(Liveness event) {
    }

    /** An actuator reached its safe state. */
    default void actuatorStopped(ActuatorStopped event) {
    }

    /** A simulator published where a robot is and what it senses. */
    default void groundTruth(GroundTruth frame) {
    }

    /**
     * The space replays a recording ({@code rwe replay}): what follows happened earlier, not now, and no hardware
     * is driven. Called once, before the first event, when the tap finds the space's {@link ReplayMark}.
     */
    default void replay(ReplayMark mark) {
    }

    /** Events may be missing (or watching ended): what an observer shows may be incomplete until the next one. */
    default void gap(Gap gap) {
    }
}
