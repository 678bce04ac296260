package robotworld.observe;

import java.util.List;
import java.util.Objects;
import java.util.stream.Stream;

/**
 * What a tap watches: a world's name and its participants with their modules.
 *
 * @param world        the world's name
 * @param participants environments and robots, in description order
 */
public record WorldLayout(String world, List<Participant> participants) {

    /** Copies the list. */
    public WorldLayout {
        Objects.requireNonNull(world, "world");
        participants = List.copyOf(participants);
    }

    /**
     * A robot or an environment.
     *
     * @param name    its name
     * @param kind    {@code robot} or {@code environment}
     * @param modules its modules
     */
    public record Participant(String name, String kind, List<ModuleRef> modules) {

        /** Copies the list. */
        public Participant {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(kind, "kind");
            modules = List.copyOf(modules);
        }

        /** Whether it is a robot (and may have a simulator publishing its ground truth). */
        public boolean isRobot() {
            return "robot".equals(kind);
        }
    }

    /** Every module of every participant. */
    public List<ModuleRef> modules() {
        return participants.stream().flatMap(participant -> participant.modules().stream()).toList();
    }

    /** Only the modules that {@code keep} accepts (participants without any are left out). */
    public WorldLayout only(java.util.function.Predicate<ModuleRef> keep) {
        return new WorldLayout(world, participants.stream()
                .map(p -> new Participant(p.name(), p.kind(), p.modules().stream().filter(keep).toList()))
                .filter(p -> !p.modules().isEmpty()).toList());
    }

    /** The robots' names. */
    public Stream<String> robots() {
        return participants.stream().filter(Participant::isRobot).map(Participant::name);
    }
}
