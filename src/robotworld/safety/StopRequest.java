package robotworld.safety;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;

/**
 * A request to stop every actuator of a world ({@code rwe stop}, a STOP button), shifted into the
 * {@value SafetyContainers#STOP_REQUESTS} container. Every program that serves actuators watches the container,
 * stops its actuators of the named participants at once, and answers with one {@link StopAnswer} per module.
 *
 * <p>Tuple layout: {@code <id, from, reason, participants, atMillis>}, e.g.
 * {@code <"stop-3f2a9c", "ops-laptop", "rwe stop", <"CaterpillarRobot", "DimRoom">, 1764000000123>}; an empty
 * participants tuple means every participant served through the space.
 *
 * @param id           unique per request; the answers carry it
 * @param from         who asks (a host name, or {@code host (STOP button)})
 * @param reason       why, in words
 * @param participants whose actuators to stop; empty for all
 * @param at           when it was asked (the asking computer's clock)
 */
public record StopRequest(String id, String from, String reason, List<String> participants, Instant at) {

    private static final int ARITY = 5;

    /** Copies the list. */
    public StopRequest {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(from, "from");
        Objects.requireNonNull(reason, "reason");
        participants = List.copyOf(participants);
        Objects.requireNonNull(at, "at");
    }

    /** Whether the request concerns {@code participant}. */
    public boolean concerns(String participant) {
        return participants.isEmpty() || participants.contains(participant);
    }

    /** The tuple stored in the space. */
    public Tuple toTuple() {
        List<Entry> names = new ArrayList<>(participants.size());
        participants.forEach(name -> names.add(Entry.of(name)));
        return Tuple.of(Entry.of(id), Entry.of(from), Entry.of(reason), new Tuple(names), Entry.of(at.toEpochMilli()));
    }

    /**
     * Reads a stop request from the space.
     *
     * @throws IllegalArgumentException when the entry does not have the layout
     */
    public static StopRequest parse(Entry entry) {
        if (!(entry instanceof Tuple tuple) || tuple.arity() != ARITY || !(tuple.get(0) instanceof StringEntry id)
                || !(tuple.get(1) instanceof StringEntry from) || !(tuple.get(2) instanceof StringEntry reason)
                || !(tuple.get(3) instanceof Tuple names) || !(tuple.get(4) instanceof IntEntry at)) {
            throw new IllegalArgumentException("not a stop request <id, from, reason, participants, atMillis>: "
                    + entry);
        }
        List<String> participants = new ArrayList<>(names.arity());
        for (Entry name : names.fields()) {
            if (!(name instanceof StringEntry text)) {
                throw new IllegalArgumentException("a participant name in a stop request is not a string: " + entry);
            }
            participants.add(text.value());
        }
        return new StopRequest(id.value(), from.value(), reason.value(), participants, Instant.ofEpochMilli(at.value()));
    }
}
