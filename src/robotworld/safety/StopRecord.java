package robotworld.safety;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Objects;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;

/**
 * One actuator put into its safe state: who, why, when and what was done. Logged by the program that stopped it,
 * published in the space's {@value SafetyContainers#STOPS} container, shown by monitors, and told to the
 * actuator's commanders on their next call.
 *
 * <p>Tuple layout (every field always present, empty strings for "none"):
 * {@code <atMillis, participant, module, cause, reason, action, stoppedBy, commander, request>}, e.g.
 * {@code <1764000000123, "CaterpillarRobot", "Motor-Controller", "commander-silent",
 * "laptop#k3x9 silent for 512 ms (command timeout 500 ms)", "motors 1-8 set to 0", "robot-pc#q1w2", "laptop#k3x9", "">}.
 *
 * @param at          when it was stopped (the stopping computer's clock)
 * @param participant the robot or environment the actuator belongs to
 * @param module      the module's name
 * @param cause       why
 * @param reason      why, in words
 * @param action      what stopping did, e.g. {@code motors 1-8 set to 0}, or {@code failed: ...}
 * @param stoppedBy   the program that stopped it ({@code host#run}), or the module itself for a watchdog
 * @param commander   the commander it was stopped for (the silent or ended one), or empty
 * @param request     the id of the stop request it answers, or empty
 */
public record StopRecord(Instant at, String participant, String module, StopCause cause, String reason,
                         String action, String stoppedBy, String commander, String request) {

    private static final int ARITY = 9;
    private static final DateTimeFormatter CLOCK = DateTimeFormatter.ofPattern("HH:mm:ss.SSS")
            .withZone(ZoneId.systemDefault());

    /** Checks the fields; nulls become empty strings. */
    public StopRecord {
        Objects.requireNonNull(at, "at");
        Objects.requireNonNull(cause, "cause");
        participant = orEmpty(participant);
        module = orEmpty(module);
        reason = orEmpty(reason);
        action = orEmpty(action);
        stoppedBy = orEmpty(stoppedBy);
        commander = orEmpty(commander);
        request = orEmpty(request);
    }

    /** The same record with what stopping did. */
    public StopRecord withAction(String newAction) {
        return new StopRecord(at, participant, module, cause, reason, newAction, stoppedBy, commander, request);
    }

    /** The tuple stored in the space. */
    public Tuple toTuple() {
        return Tuple.of(at.toEpochMilli(), participant, module, cause.wireName(), reason, action, stoppedBy,
                commander, request);
    }

    /**
     * Reads a stop record from the space.
     *
     * @throws IllegalArgumentException when the entry does not have the layout
     */
    public static StopRecord parse(Entry entry) {
        if (!(entry instanceof Tuple tuple) || tuple.arity() != ARITY || !(tuple.get(0) instanceof IntEntry at)) {
            throw new IllegalArgumentException("not a stop record <atMillis, participant, module, cause, reason, "
                    + "action, stoppedBy, commander, request>: " + entry);
        }
        return new StopRecord(Instant.ofEpochMilli(at.value()), text(tuple, 1), text(tuple, 2),
                StopCause.ofWireName(text(tuple, 3)), text(tuple, 4), text(tuple, 5), text(tuple, 6),
                text(tuple, 7), text(tuple, 8));
    }

    /** {@code Participant/Module}. */
    public String where() {
        return participant + "/" + module;
    }

    /** The local time of day it happened, {@code HH:mm:ss.SSS}. */
    public String clockTime() {
        return CLOCK.format(at);
    }

    /**
     * One line for logs and panels: {@code stopped at 12:00:01.234 by robot-pc#q1w2 (commander-silent: ...):
     * motors 1-8 set to 0}.
     */
    public String summary() {
        return "stopped at " + clockTime() + " by " + (stoppedBy.isEmpty() ? "?" : stoppedBy) + " (" + cause.wireName()
                + (reason.isEmpty() ? "" : ": " + reason) + ")" + (action.isEmpty() ? "" : ": " + action);
    }

    @Override
    public String toString() {
        return where() + " " + summary();
    }

    private static String orEmpty(String text) {
        return text == null ? "" : text;
    }

    private static String text(Tuple tuple, int index) {
        Entry field = tuple.get(index);
        if (!(field instanceof StringEntry text)) {
            throw new IllegalArgumentException("field " + (index + 1) + " of a stop record is not a string: " + tuple);
        }
        return text.value();
    }
}
