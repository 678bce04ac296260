package robotworld.telemetry;

import java.time.Instant;
import java.util.Objects;
import java.util.function.Consumer;
import robotworld.observe.ActuatorStopped;
import robotworld.observe.AnswerSeen;
import robotworld.observe.Gap;
import robotworld.observe.GroundTruth;
import robotworld.observe.Liveness;
import robotworld.observe.RequestSeen;
import robotworld.observe.WorldObserver;

/**
 * Turns a tap's events into JSON messages for a sink (a recorder, a Foxglove endpoint). Runs on the tap's
 * thread, so the sink must take a message quickly and never block.
 */
public final class WorldTelemetry implements WorldObserver {

    private final Consumer<TelemetryMessage> sink;

    /** Hands every message to {@code sink}. */
    public WorldTelemetry(Consumer<TelemetryMessage> sink) {
        this.sink = Objects.requireNonNull(sink, "sink");
    }

    @Override
    public void requestSeen(RequestSeen event) {
        send(Topics.module(event.module()), event.at(), TrafficJson.request(event));
    }

    @Override
    public void answerSeen(AnswerSeen event) {
        send(Topics.module(event.module()), event.at(), TrafficJson.answer(event));
    }

    @Override
    public void liveness(Liveness event) {
        send(Topics.LIVENESS, Instant.now(), TrafficJson.liveness(event));
    }

    @Override
    public void actuatorStopped(ActuatorStopped event) {
        send(Topics.STOPS, event.at(), TrafficJson.stopped(event));
    }

    @Override
    public void groundTruth(GroundTruth frame) {
        String robot = frame.robot();
        send(Topics.groundTruth(robot), frame.at(), TrafficJson.groundTruth(frame));
        send(Topics.TRANSFORMS, frame.at(), GroundTruthScene.transforms(frame));
        send(Topics.pose(robot), frame.at(), GroundTruthScene.pose(frame));
        send(Topics.scene(robot), frame.at(), GroundTruthScene.scene(frame));
        for (GroundTruth.Ray ray : frame.rays()) {
            send(Topics.ir(robot, ray.address(), ray.sensor()), frame.at(), GroundTruthScene.scan(frame, ray));
        }
    }

    @Override
    public void gap(Gap gap) {
        send(Topics.GAPS, gap.at(), TrafficJson.gap(gap));
    }

    private void send(Topic topic, Instant at, com.fasterxml.jackson.databind.JsonNode json) {
        sink.accept(new TelemetryMessage(topic, nanos(at), TrafficJson.bytes(json)));
    }

    /** Nanoseconds since the epoch. */
    public static long nanos(Instant at) {
        return at.getEpochSecond() * 1_000_000_000L + at.getNano();
    }
}
