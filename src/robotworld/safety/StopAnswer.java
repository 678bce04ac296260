package robotworld.safety;

import java.util.Locale;
import java.util.Objects;
import robotworld.space.Entry;
import robotworld.space.StringEntry;
import robotworld.space.Template;
import robotworld.space.Tuple;

/**
 * What a program did with a {@link StopRequest} for one module it serves, shifted into the
 * {@value SafetyContainers#STOP_ANSWERS} container.
 *
 * <p>Tuple layout: {@code <request, participant, module, by, state, detail>}, e.g.
 * {@code <"stop-3f2a9c", "CaterpillarRobot", "Motor-Controller", "robot-pc#q1w2", "stopped", "motors 1-8 set to 0">};
 * state {@code stopped} (an actuator, now in its safe state), {@code failed} (an actuator whose safe state could
 * not be reached: detail says why) or {@code no-actuator} (a sensor: nothing to stop).
 *
 * @param request     the stop request's id
 * @param participant the module's participant
 * @param module      the module's name
 * @param by          the program that answers ({@code host#run})
 * @param state       what happened
 * @param detail      what stopping did, or why it failed
 */
public record StopAnswer(String request, String participant, String module, String by, State state, String detail) {

    private static final int ARITY = 6;

    /** What happened to one module. */
    public enum State {
        /** An actuator, now in its safe state. */
        STOPPED,
        /** An actuator whose safe state could not be reached. */
        FAILED,
        /** A sensor: nothing to stop. */
        NO_ACTUATOR;

        /** {@code stopped}, {@code failed}, {@code no-actuator}. */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT).replace('_', '-');
        }

        static State ofWireName(String name) {
            for (State state : values()) {
                if (state.wireName().equals(name)) {
                    return state;
                }
            }
            return FAILED;
        }
    }

    /** Checks the fields. */
    public StopAnswer {
        Objects.requireNonNull(request, "request");
        Objects.requireNonNull(participant, "participant");
        Objects.requireNonNull(module, "module");
        Objects.requireNonNull(by, "by");
        Objects.requireNonNull(state, "state");
        detail = detail == null ? "" : detail;
    }

    /** The tuple stored in the space. */
    public Tuple toTuple() {
        return Tuple.of(request, participant, module, by, state.wireName(), detail);
    }

    /** A template matching every answer to {@code request}. */
    public static Template answersTo(String request) {
        return Template.tuple(request, Template.ANY, Template.ANY, Template.ANY, Template.ANY, Template.ANY);
    }

    /**
     * Reads a stop answer from the space.
     *
     * @throws IllegalArgumentException when the entry does not have the layout
     */
    public static StopAnswer parse(Entry entry) {
        if (!(entry instanceof Tuple tuple) || tuple.arity() != ARITY) {
            throw new IllegalArgumentException("not a stop answer <request, participant, module, by, state, detail>: "
                    + entry);
        }
        for (Entry field : tuple.fields()) {
            if (!(field instanceof StringEntry)) {
                throw new IllegalArgumentException("a stop answer has only string fields: " + entry);
            }
        }
        return new StopAnswer(tuple.stringAt(0), tuple.stringAt(1), tuple.stringAt(2), tuple.stringAt(3),
                State.ofWireName(tuple.stringAt(4)), tuple.stringAt(5));
    }
}
