package robotworld.safety;

import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Order;

/**
 * The space containers of the safety layer. Their names contain a dot, which no participant or module name can
 * (they are Java identifiers and module names), so they never clash with a module's {@code REQUEST}/{@code ANSWER}
 * containers. Every party looks them up or creates them with these specs; all are bounded FIFOs written with
 * {@code shift}, so the oldest entries make room and nothing grows without limit. Layouts: {@code docs/runtime.md}.
 */
public final class SafetyContainers {

    /** Heartbeats, one entry per program under the key {@code host#run}: see {@link Heartbeat}. */
    public static final String LIVENESS = "rwe.liveness";
    /** Stop records, one per actuator stopped: see {@link StopRecord}. */
    public static final String STOPS = "rwe.stops";
    /** Requests to stop a world ({@code rwe stop}, STOP buttons): see {@link StopRequest}. */
    public static final String STOP_REQUESTS = "rwe.stop.requests";
    /** One answer per module to each stop request: see {@link StopAnswer}. */
    public static final String STOP_ANSWERS = "rwe.stop.answers";

    static final int LIVENESS_CAPACITY = 1024;
    static final int STOPS_CAPACITY = 1000;
    static final int STOP_REQUESTS_CAPACITY = 64;
    static final int STOP_ANSWERS_CAPACITY = 4096;

    private SafetyContainers() {
    }

    /** {@value #LIVENESS}: FIFO with a KEY view, at most 1024 programs (the longest silent make room). */
    public static ContainerSpec livenessSpec() {
        return ContainerSpec.of(Order.FIFO).withKeyView().bounded(LIVENESS_CAPACITY).named(LIVENESS);
    }

    /** {@value #STOPS}: FIFO, the newest 1000 stop records. */
    public static ContainerSpec stopsSpec() {
        return ContainerSpec.of(Order.FIFO).bounded(STOPS_CAPACITY).named(STOPS);
    }

    /** {@value #STOP_REQUESTS}: FIFO, the newest 64 stop requests. */
    public static ContainerSpec stopRequestsSpec() {
        return ContainerSpec.of(Order.FIFO).bounded(STOP_REQUESTS_CAPACITY).named(STOP_REQUESTS);
    }

    /** {@value #STOP_ANSWERS}: FIFO, the newest 4096 answers. */
    public static ContainerSpec stopAnswersSpec() {
        return ContainerSpec.of(Order.FIFO).bounded(STOP_ANSWERS_CAPACITY).named(STOP_ANSWERS);
    }

    /** Looks up or creates the liveness container. */
    public static ContainerRef liveness(Capi space) {
        return space.lookupOrCreateContainer(livenessSpec());
    }

    /** Looks up or creates the stop-record container. */
    public static ContainerRef stops(Capi space) {
        return space.lookupOrCreateContainer(stopsSpec());
    }

    /** Looks up or creates the stop-request container. */
    public static ContainerRef stopRequests(Capi space) {
        return space.lookupOrCreateContainer(stopRequestsSpec());
    }

    /** Looks up or creates the stop-answer container. */
    public static ContainerRef stopAnswers(Capi space) {
        return space.lookupOrCreateContainer(stopAnswersSpec());
    }
}
