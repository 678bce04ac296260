package robotworld.safety;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;

/**
 * A program's sign of life in the {@value SafetyContainers#LIVENESS} container, shifted under the key {@link #id()}
 * every heartbeat period (100 ms by default), and once more with state {@code ended} when the program closes.
 *
 * <p>Tuple layout: {@code <id, host, serves, state, sequence, periodMillis, sentAtMillis>}, e.g.
 * {@code <"robot-pc#q1w2", "robot-pc", <<"CaterpillarRobot", "Motor-Controller">, <"CaterpillarRobot",
 * "Bumper-Sensor">>, "alive", 4711, 100, 1764000000123>}.
 *
 * <p>Readers judge liveness by the {@link #sequence} changing, measured with their own clock: the sender's clock
 * ({@link #sentAtMillis}) is for display only, as the computers' clocks need not agree. A program whose sequence
 * has not changed for a few periods is presumed dead; one whose state is {@code ended} has closed cleanly.
 *
 * @param id           {@code host#run}: the program, as it appears in the keys of its module calls
 * @param host         the program's host name
 * @param serves       the modules the program serves (it has their hardware), as participant/module pairs
 * @param ended        whether the program has ended (state {@code ended}; else {@code alive})
 * @param sequence     counts the program's heartbeats
 * @param periodMillis how often the program sends one
 * @param sentAtMillis the sender's clock when sent
 */
public record Heartbeat(String id, String host, List<ModuleName> serves, boolean ended, long sequence,
                        long periodMillis, long sentAtMillis) {

    /** State of a running program. */
    public static final String ALIVE = "alive";
    /** State of a program that closed cleanly. */
    public static final String ENDED = "ended";

    private static final int ARITY = 7;

    /** A participant/module pair. */
    public record ModuleName(String participant, String module) {

        /** Checks the names. */
        public ModuleName {
            Objects.requireNonNull(participant, "participant");
            Objects.requireNonNull(module, "module");
        }

        @Override
        public String toString() {
            return participant + "/" + module;
        }
    }

    /** Copies the list. */
    public Heartbeat {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(host, "host");
        serves = List.copyOf(serves);
    }

    /** The tuple stored in the space. */
    public Tuple toTuple() {
        List<Entry> modules = new ArrayList<>(serves.size());
        for (ModuleName name : serves) {
            modules.add(Tuple.of(name.participant(), name.module()));
        }
        return Tuple.of(Entry.of(id), Entry.of(host), new Tuple(modules), Entry.of(ended ? ENDED : ALIVE),
                Entry.of(sequence), Entry.of(periodMillis), Entry.of(sentAtMillis));
    }

    /**
     * Reads a heartbeat from the space.
     *
     * @throws IllegalArgumentException when the entry does not have the layout
     */
    public static Heartbeat parse(Entry entry) {
        if (!(entry instanceof Tuple tuple) || tuple.arity() != ARITY
                || !(tuple.get(0) instanceof StringEntry id) || !(tuple.get(1) instanceof StringEntry host)
                || !(tuple.get(2) instanceof Tuple served) || !(tuple.get(3) instanceof StringEntry state)
                || !(tuple.get(4) instanceof IntEntry sequence) || !(tuple.get(5) instanceof IntEntry period)
                || !(tuple.get(6) instanceof IntEntry sentAt)) {
            throw new IllegalArgumentException("not a heartbeat <id, host, serves, state, sequence, periodMillis, "
                    + "sentAtMillis>: " + entry);
        }
        List<ModuleName> modules = new ArrayList<>(served.arity());
        for (Entry module : served.fields()) {
            if (!(module instanceof Tuple pair) || pair.arity() != 2 || !(pair.get(0) instanceof StringEntry p)
                    || !(pair.get(1) instanceof StringEntry m)) {
                throw new IllegalArgumentException("not a <participant, module> pair in a heartbeat: " + module);
            }
            modules.add(new ModuleName(p.value(), m.value()));
        }
        return new Heartbeat(id.value(), host.value(), modules, ENDED.equals(state.value()), sequence.value(),
                period.value(), sentAt.value());
    }

    /** Whether this program serves a module of {@code participant}. */
    public boolean servesParticipant(String participant) {
        return serves.stream().anyMatch(name -> name.participant().equals(participant));
    }
}
