package robotworld.safety;

import java.time.Clock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * The safety state of one actuator served by this program: who commands it, whether a stop is owed to a
 * commander as a notice, and the stop itself. The serving side asks it before every command ({@link #admit}) and
 * tells it afterwards ({@link #performed}); the {@link SafetySupervisor} stops it ({@link #stop}).
 *
 * <p><b>Commanders</b> are programs, named {@code host#run} as in the keys of their calls; the program serving
 * the actuator commands it under its own id. The <i>engagers</i> are the commanders whose commands have kept the
 * actuator away from its safe state since it was last at rest: losing one of them stops it.
 *
 * <p><b>Notices.</b> After a stop, commanders that had commanded the actuator are owed a notice: their next
 * command is refused (and not carried out) with the stop record, so that a program that comes back learns that it
 * must command again. A command that cannot carry an answer back (a remote quiet call) is refused while the notice
 * is owed, without settling it. Once the program serving the actuator ends, every command is refused.
 *
 * <p><b>Holding.</b> While the serving program cannot reach its space, the actuator may be {@linkplain #hold held}
 * in its safe state: every command is refused with the reason until {@link #release}, because nobody elsewhere
 * could stop what it would start. A commander refused while it is held has been told.
 *
 * <p><b>Races.</b> Commands run without a lock on the hardware; a stop that happens while a command is being
 * carried out is noticed by {@link #performed}, which puts the actuator into its safe state once more, so a
 * command that started before a stop can never leave the actuator moving after it.
 *
 * <p>Thread-safe.
 */
public final class ActuatorGuard {

    /** Receives every stop of the actuator, to log and publish it. */
    public interface StopListener {
        void stopped(StopRecord record);
    }

    /**
     * The answer to {@link #admit}: carry the command out, or refuse it with the stop the commander is told of.
     *
     * @param held whether it was refused because the actuator is {@linkplain #hold held}, not for a stop it owes
     */
    public record Admission(long epoch, StopRecord refusal, boolean held) {

        /** Whether the command may be carried out. */
        public boolean admitted() {
            return refusal == null;
        }

        /** What the refused commander can do about it, in words. */
        public String advice() {
            return held ? "it takes commands again once " + refusal.stoppedBy() + " reaches its space"
                    : "command it again to move it";
        }
    }

    /** How long a commander that never calls again is remembered. */
    static final long FORGET_NANOS = TimeUnit.MINUTES.toNanos(10);
    /** A failed stop is tried again at most this often by the rules that stop on silence. */
    static final long RETRY_NANOS = TimeUnit.SECONDS.toNanos(1);

    private static final class Known {
        long lastCommandNanos;
        StopRecord owed;
    }

    private final String participant;
    private final String module;
    private final Actuator actuator;
    private final String ownId;
    private final StopListener listener;
    private final Clock clock;
    private final Object lock = new Object();
    private final Map<String, Known> commanders = new HashMap<>();
    private final Set<String> engagers = new LinkedHashSet<>();
    private volatile Duration commandTimeout;
    private long epoch;
    private StopRecord ended;
    private StopRecord held;
    private long lastFailedStopNanos;
    private boolean lastStopFailed;

    /**
     * @param participant    the actuator's participant
     * @param module         the actuator's module name
     * @param actuator       the actuator
     * @param ownId          the serving program's id ({@code host#run}): its own commands
     * @param commandTimeout how long a remote commander may be silent
     * @param listener       told of every stop
     */
    public ActuatorGuard(String participant, String module, Actuator actuator, String ownId, Duration commandTimeout,
                         StopListener listener) {
        this(participant, module, actuator, ownId, commandTimeout, listener, Clock.systemUTC());
    }

    ActuatorGuard(String participant, String module, Actuator actuator, String ownId, Duration commandTimeout,
                  StopListener listener, Clock clock) {
        this.participant = Objects.requireNonNull(participant, "participant");
        this.module = Objects.requireNonNull(module, "module");
        this.actuator = Objects.requireNonNull(actuator, "actuator");
        this.ownId = Objects.requireNonNull(ownId, "ownId");
        this.listener = Objects.requireNonNull(listener, "listener");
        this.clock = clock;
        setCommandTimeout(commandTimeout);
    }

    public String participant() {
        return participant;
    }

    public String module() {
        return module;
    }

    /** The actuator guarded. */
    public Actuator actuator() {
        return actuator;
    }

    /** How long a remote commander of this actuator may be silent before it is stopped. */
    public Duration commandTimeout() {
        return commandTimeout;
    }

    /** Changes the command timeout; takes effect at the next check. */
    public void setCommandTimeout(Duration timeout) {
        this.commandTimeout = SafetySettings.checkCommandTimeout(timeout);
    }

    /**
     * Asks whether a command of {@code commander} may be carried out; also notes that the commander was heard from.
     *
     * @param canBeTold whether the command's caller receives an answer (a remote quiet call does not)
     */
    public Admission admit(String commander, boolean canBeTold) {
        synchronized (lock) {
            if (ended != null) {
                return new Admission(epoch, ended, false);
            }
            Known known = commanders.computeIfAbsent(commander, c -> new Known());
            known.lastCommandNanos = System.nanoTime();
            StopRecord owed = known.owed;
            if (owed != null && canBeTold) {
                known.owed = null; // told now, whether by this stop or by the hold
            }
            if (held != null) {
                return new Admission(epoch, held, true);
            }
            if (owed != null) {
                return new Admission(epoch, owed, false);
            }
            return new Admission(epoch, null, false);
        }
    }

    /**
     * After an admitted command was carried out (or failed): records who keeps the actuator engaged, and puts it
     * into its safe state again if a stop happened meanwhile.
     */
    public void performed(String commander, Admission admission) {
        boolean stoppedMeanwhile;
        synchronized (lock) {
            stoppedMeanwhile = admission.epoch() != epoch || ended != null;
            if (!stoppedMeanwhile) {
                if (actuator.isEngaged()) {
                    engagers.add(commander);
                } else {
                    engagers.clear();
                }
            }
        }
        if (stoppedMeanwhile) {
            try {
                actuator.enterSafeState();
            } catch (Exception e) {
                // the stop that happened meanwhile reported its own outcome; the rules try again while engaged
            }
        }
    }

    /** Whether the actuator may be away from its safe state. */
    public boolean isEngaged() {
        return actuator.isEngaged();
    }

    /** The commanders, other than the serving program itself, that keep the actuator engaged. */
    public List<String> remoteEngagers() {
        synchronized (lock) {
            List<String> remote = new ArrayList<>(engagers.size());
            for (String engager : engagers) {
                if (!engager.equals(ownId)) {
                    remote.add(engager);
                }
            }
            return remote;
        }
    }

    /** When {@code commander} last sent a command, by {@link System#nanoTime()}; 0 if never. */
    public long lastCommandNanos(String commander) {
        synchronized (lock) {
            Known known = commanders.get(commander);
            return known == null ? 0 : known.lastCommandNanos;
        }
    }

    /**
     * Whether a rule that stops on silence may stop now: always, unless the last stop failed less than a second ago
     * (the hardware is not reachable; trying every few milliseconds would only flood the log).
     */
    public boolean mayRetryStop() {
        synchronized (lock) {
            return !lastStopFailed || System.nanoTime() - lastFailedStopNanos > RETRY_NANOS;
        }
    }

    /**
     * Puts the actuator into its safe state and tells the listener.
     *
     * @param cause        why
     * @param reason       why, in words
     * @param forCommander the commander it is stopped for (silent or ended), or null
     * @param request      the stop request it answers, or null
     * @return the stop record, with what was done (or {@code failed: ...})
     */
    public StopRecord stop(StopCause cause, String reason, String forCommander, String request) {
        return stop(cause, reason, forCommander, request, false);
    }

    /**
     * {@link #stop} and, with {@code hold}, {@linkplain #hold holds} the actuator from the same moment: no command
     * slips in between to be told "command it again" while it is held.
     */
    public StopRecord stop(StopCause cause, String reason, String forCommander, String request, boolean hold) {
        StopRecord record = new StopRecord(clock.instant(), participant, module, cause, reason, "", ownId,
                forCommander, request);
        synchronized (lock) {
            epoch++;
            if (hold && held == null) {
                held = record;
            }
            if (cause.endsTheProgram()) {
                ended = record;
            } else if (cause == StopCause.COMMANDER_SILENT || cause == StopCause.COMMANDER_ENDED) {
                owe(engagers, record);
            } else {
                owe(commanders.keySet(), record);
            }
            forgetOldCommanders();
        }
        String action;
        boolean failed;
        try {
            action = actuator.enterSafeState();
            failed = false;
        } catch (Exception e) {
            action = "failed: " + (e.getMessage() == null ? e.toString() : e.getMessage());
            failed = true;
        }
        StopRecord done = record.withAction(action);
        synchronized (lock) {
            lastStopFailed = failed;
            if (failed) {
                lastFailedStopNanos = System.nanoTime();
            } else {
                engagers.clear();
            }
            // the notices tell what was done
            for (Known known : commanders.values()) {
                if (known.owed == record) {
                    known.owed = done;
                }
            }
            if (ended == record) {
                ended = done;
            }
            if (held == record) {
                held = done;
            }
        }
        listener.stopped(done);
        return done;
    }

    /**
     * Holds the actuator in its safe state: every command is refused with {@code why} until {@link #release}; a
     * command under way is undone when it completes ({@link #performed}). An engaged actuator is stopped and held
     * at once by {@link #stop(StopCause, String, String, String, boolean)}. A second hold keeps the first reason.
     */
    public void hold(StopRecord why) {
        Objects.requireNonNull(why, "why");
        synchronized (lock) {
            if (held == null) {
                held = why;
                epoch++;
            }
        }
    }

    /** Ends a {@link #hold}: commands are admitted again (a stop still owed is told first). */
    public void release() {
        synchronized (lock) {
            held = null;
        }
    }

    /** Whether the actuator is {@linkplain #hold held}. */
    public boolean isHeld() {
        synchronized (lock) {
            return held != null;
        }
    }

    /** Whether the program serving the actuator has ended (every command is refused). */
    public boolean hasEnded() {
        synchronized (lock) {
            return ended != null;
        }
    }

    @Override
    public String toString() {
        return "ActuatorGuard[" + participant + "/" + module + "]";
    }

    private void owe(Iterable<String> who, StopRecord record) {
        for (String commander : who) {
            commanders.computeIfAbsent(commander, c -> new Known()).owed = record;
        }
    }

    private void forgetOldCommanders() {
        long now = System.nanoTime();
        commanders.entrySet().removeIf(e -> e.getValue().owed == null && !engagers.contains(e.getKey())
                && now - e.getValue().lastCommandNanos > FORGET_NANOS);
    }
}
