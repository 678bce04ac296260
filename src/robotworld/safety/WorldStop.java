package robotworld.safety;

import java.security.SecureRandom;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.Timeout;

/**
 * Stops a whole world through its space, from any computer: shifts a {@link StopRequest} into the space, which
 * every program serving actuators of the named participants carries out at once, and collects their
 * {@link StopAnswer}s. What {@code rwe stop} and the STOP buttons do.
 *
 * <pre>{@code
 * WorldStop.Result result = WorldStop.stop(space, "ops-laptop", "rwe stop", targets, Duration.ofSeconds(2));
 * result.outcomes().forEach(o -> System.out.println(o));
 * }</pre>
 */
public final class WorldStop {

    /** How long {@code rwe stop} waits for answers by default. */
    public static final Duration DEFAULT_WAIT = Duration.ofSeconds(2);
    private static final long POLL_NANOS = TimeUnit.MILLISECONDS.toNanos(5);
    private static final SecureRandom RANDOM = new SecureRandom();

    /**
     * A module the stop is for.
     *
     * @param participant its participant
     * @param module      its name
     * @param actuator    whether it is (or may be) an actuator: one that cannot be reached is a failure of the stop;
     *                    a sensor that cannot be reached is only reported
     */
    public record Target(String participant, String module, boolean actuator) {

        /** Checks the names. */
        public Target {
            Objects.requireNonNull(participant, "participant");
            Objects.requireNonNull(module, "module");
        }

        @Override
        public String toString() {
            return participant + "/" + module;
        }
    }

    /**
     * What happened to one target.
     *
     * @param target    the module
     * @param answer    the answer of the program serving it, or null when none came in time
     * @param lastHeard for a target without answer, the program that last said (in a heartbeat) that it serves the
     *                  module, or null
     */
    public record Outcome(Target target, StopAnswer answer, String lastHeard) {

        /** Whether its program answered. */
        public boolean reached() {
            return answer != null;
        }

        /** Whether this outcome makes the stop incomplete: an actuator not reached, or one that failed to stop. */
        public boolean isFailure() {
            return answer == null ? target.actuator()
                    : answer.state() == StopAnswer.State.FAILED;
        }

        /** One line: {@code SafetyBot/Motor  stopped by robot-pc#q1w2: motors 1-8 set to 0}. */
        @Override
        public String toString() {
            if (answer == null) {
                return target + "  unreachable" + (target.actuator() ? "" : " (a sensor: nothing to stop)")
                        + (lastHeard == null ? ": no program serving it answered"
                        : ": its program " + lastHeard + " did not answer");
            }
            return target + "  " + switch (answer.state()) {
                case STOPPED -> "stopped by " + answer.by() + ": " + answer.detail();
                case FAILED -> "FAILED at " + answer.by() + ": " + answer.detail();
                case NO_ACTUATOR -> "no actuator (" + answer.by() + ")";
            };
        }
    }

    /**
     * The outcome of a stop.
     *
     * @param request  the request sent
     * @param outcomes one per target, in the targets' order, then answers for modules that were not targets
     * @param elapsed  from sending the request to the last answer (or the end of the wait)
     */
    public record Result(StopRequest request, List<Outcome> outcomes, Duration elapsed) {

        /** Copies the list. */
        public Result {
            outcomes = List.copyOf(outcomes);
        }

        /** Whether every actuator answered that it is stopped. */
        public boolean complete() {
            return outcomes.stream().noneMatch(Outcome::isFailure);
        }

        /** The outcomes that make the stop incomplete. */
        public List<Outcome> failures() {
            return outcomes.stream().filter(Outcome::isFailure).toList();
        }
    }

    private WorldStop() {
    }

    /**
     * Asks every program serving a target to stop its actuators, and waits up to {@code wait} for every target's
     * answer.
     *
     * @param from    who asks, for the records (a host name; {@code host (STOP button)})
     * @param reason  why, in words
     * @param targets the modules of the world; their participants are the request's (none: every participant)
     * @param wait    how long to wait for answers
     * @throws robotworld.space.SpaceException when the request cannot be written into the space
     */
    public static Result stop(Capi space, String from, String reason, List<Target> targets, Duration wait)
            throws InterruptedException {
        Set<String> participants = new LinkedHashSet<>();
        targets.forEach(target -> participants.add(target.participant()));
        StopRequest request = new StopRequest(newId(), from, reason, List.copyOf(participants), Instant.now());
        long start = System.nanoTime();
        ContainerRef answers = SafetyContainers.stopAnswers(space);
        space.shift(SafetyContainers.stopRequests(space), Timeout.of(wait), List.of(Item.of(request.toTuple())));
        Map<String, StopAnswer> received = new LinkedHashMap<>();
        long deadline = start + wait.toNanos();
        while (true) {
            for (Entry entry : space.read(answers, Timeout.TRY_ONCE,
                    Selector.template(StopAnswer.answersTo(request.id()), Selector.ALL))) {
                StopAnswer answer = StopAnswer.parse(entry);
                received.putIfAbsent(answer.participant() + "/" + answer.module(), answer);
            }
            boolean all = !targets.isEmpty() && targets.stream().allMatch(t -> received.containsKey(t.toString()));
            if (all || System.nanoTime() - deadline > 0) {
                break;
            }
            TimeUnit.NANOSECONDS.sleep(POLL_NANOS);
        }
        Duration elapsed = Duration.ofNanos(System.nanoTime() - start);
        Map<String, String> servedBy = targets.stream().allMatch(t -> received.containsKey(t.toString()))
                ? Map.of() : lastServers(space);
        List<Outcome> outcomes = new ArrayList<>();
        for (Target target : targets) {
            StopAnswer answer = received.remove(target.toString());
            outcomes.add(new Outcome(target, answer, answer == null ? servedBy.get(target.toString()) : null));
        }
        for (StopAnswer extra : received.values()) {
            outcomes.add(new Outcome(new Target(extra.participant(), extra.module(),
                    extra.state() != StopAnswer.State.NO_ACTUATOR), extra, null));
        }
        return new Result(request, outcomes, elapsed);
    }

    /** For each module, the program whose last heartbeat (not an ended one) says it serves it. */
    private static Map<String, String> lastServers(Capi space) {
        Map<String, String> servers = new LinkedHashMap<>();
        try {
            for (Entry entry : space.read(SafetyContainers.liveness(space), Timeout.TRY_ONCE,
                    Selector.fifo(Selector.ALL))) {
                Heartbeat heartbeat = Heartbeat.parse(entry);
                if (!heartbeat.ended()) {
                    heartbeat.serves().forEach(name -> servers.put(name.toString(), heartbeat.id()));
                }
            }
        } catch (RuntimeException e) {
            // only a hint for the report
        }
        return servers;
    }

    private static String newId() {
        byte[] bytes = new byte[6];
        RANDOM.nextBytes(bytes);
        return "stop-" + HexFormat.of().formatHex(bytes);
    }
}
