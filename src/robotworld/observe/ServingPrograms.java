package robotworld.observe;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import robotworld.safety.Heartbeat;

/**
 * What the heartbeats in {@value robotworld.safety.SafetyContainers#LIVENESS} say about the programs that serve a
 * world's modules (see {@link Heartbeat}): a program is alive while new heartbeats of it arrive, silent once none
 * has arrived for {@link #silentAfter}, and ended when its last heartbeat says so. Time is this computer's, as
 * heartbeats are meant to be judged: the sender's clock may differ.
 *
 * <p>A module's program is the one naming it whose heartbeat arrived last, so a program restarted under a new id
 * takes over from its dead predecessor, whose entry stays in the container. A program keeps the modules it has
 * named: one that closes releases its actuators, and names them no more, before its last heartbeat. Thread-safe:
 * heartbeats arrive on the space's delivery threads and are judged on the tap's dispatch thread.
 */
final class ServingPrograms {

    /** The least time without a heartbeat before a program counts as silent. */
    static final Duration LEAST_SILENCE = Duration.ofSeconds(1);
    /** Heartbeat periods without a heartbeat before a program counts as silent, when that is longer. */
    static final int SILENT_PERIODS = 5;
    /** Programs remembered: as many as the container holds. */
    private static final int CAPACITY = 1024;

    /** What the heartbeats say about one participant. */
    record Verdict(Liveness.State state, Instant lastSign, long heardNanos, String basis) {
    }

    /** One program, as its heartbeats tell. */
    private static final class Program {
        final String id;
        List<Heartbeat.ModuleName> serves = List.of();
        long sequence = Long.MIN_VALUE;
        boolean ended;
        long periodMillis;
        /** When a new heartbeat of it last arrived (this computer's clock), or when it was first read. */
        long heardNanos;
        Instant heardAt;
        /** Whether a new heartbeat arrived while watching (one read at the start may be a dead program's). */
        boolean beating;

        Program(String id) {
            this.id = id;
        }

        /** When its last heartbeat arrived; null for one only found at the start (when it was sent is unknown). */
        Instant lastSign() {
            return beating ? heardAt : null;
        }

        long silentAfterNanos() {
            return silentAfter(periodMillis).toNanos();
        }
    }

    private final Set<String> participants;
    /** Programs serving modules of the world, the one heard from longest ago first. */
    private final LinkedHashMap<String, Program> programs = new LinkedHashMap<>(16, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Program> eldest) {
            return size() > CAPACITY;
        }
    };

    /** Heartbeats of programs serving modules of {@code participants}; others are ignored. */
    ServingPrograms(Set<String> participants) {
        this.participants = Set.copyOf(participants);
    }

    /** How long a program with heartbeats every {@code periodMillis} may be unheard before it counts as silent. */
    static Duration silentAfter(long periodMillis) {
        Duration periods = Duration.ofMillis(Math.max(0, periodMillis) * SILENT_PERIODS);
        return periods.compareTo(LEAST_SILENCE) > 0 ? periods : LEAST_SILENCE;
    }

    /**
     * A heartbeat was read.
     *
     * @param arrived whether it arrived as a new one (a notification), not found in the container at the start
     */
    synchronized void heard(Heartbeat beat, Instant at, long nanos, boolean arrived) {
        Program program = programs.get(beat.id());
        if (program == null) {
            if (beat.serves().stream().noneMatch(module -> participants.contains(module.participant()))) {
                return; // a program that only commands, or serves another world
            }
            program = new Program(beat.id());
            program.heardNanos = nanos; // silence is counted from when it was first read
            program.heardAt = at;
            programs.put(beat.id(), program);
        } else if (beat.sequence() <= program.sequence) {
            // the same heartbeat again (read once more after a subscription was renewed), or an older one that
            // arrived late: a program's heartbeats count up, and a late one must not undo the news of a newer
            return;
        }
        program.sequence = beat.sequence();
        // what it served stays its: a closing program releases its actuators before its last heartbeat
        Set<Heartbeat.ModuleName> served = new LinkedHashSet<>(program.serves);
        served.addAll(beat.serves());
        program.serves = List.copyOf(served);
        program.ended = beat.ended();
        program.periodMillis = beat.periodMillis();
        if (arrived) {
            programs.remove(beat.id());
            programs.put(beat.id(), program); // last: heard from most recently
            program.heardNanos = nanos;
            program.heardAt = at;
            program.beating = true;
        }
    }

    /**
     * What the heartbeats say about {@code participant} at {@code now} (nanos): silent if the program of any of its
     * modules is, else alive if any is, else ended if all ended. Null when no heartbeat names it, or none has told
     * yet (a program found at the start must beat, or stay silent, first).
     */
    synchronized Verdict verdict(String participant, long now) {
        Map<String, Program> current = new LinkedHashMap<>(); // module to its program: the last one heard wins
        for (Program program : programs.values()) {
            for (Heartbeat.ModuleName module : program.serves) {
                if (module.participant().equals(participant)) {
                    current.put(module.module(), program);
                }
            }
        }
        if (current.isEmpty()) {
            return null;
        }
        List<Program> alive = new ArrayList<>();
        List<Program> ended = new ArrayList<>();
        Set<Program> serving = new LinkedHashSet<>(current.values());
        for (Program program : serving) {
            if (program.ended) {
                ended.add(program);
            } else if (now - program.heardNanos > program.silentAfterNanos()) {
                return new Verdict(Liveness.State.SILENT, program.lastSign(), program.heardNanos, "no heartbeat from "
                        + program.id + (program.beating ? " for " + seconds(now - program.heardNanos) + " s"
                        : " since watching began"));
            } else if (program.beating) {
                alive.add(program);
            }
        }
        if (!alive.isEmpty()) {
            Program last = alive.get(alive.size() - 1);
            return new Verdict(Liveness.State.ALIVE, last.lastSign(), last.heardNanos, "heartbeats of " + ids(alive));
        }
        if (ended.size() == serving.size()) {
            Program last = ended.get(ended.size() - 1);
            return new Verdict(Liveness.State.ENDED, last.lastSign(), last.heardNanos, ids(ended) + " ended");
        }
        return null;
    }

    private static String ids(List<Program> programs) {
        return String.join(", ", programs.stream().map(program -> program.id).toList());
    }

    private static String seconds(long nanos) {
        return String.format(java.util.Locale.ROOT, "%.1f", nanos / 1e9);
    }
}
