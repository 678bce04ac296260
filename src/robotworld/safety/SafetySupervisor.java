package robotworld.safety;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.space.Capi;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.SpaceException;
import robotworld.space.SpaceInterruptedException;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;

/**
 * The safety layer of one program: it keeps the {@link ActuatorGuard} of every actuator the program serves and
 * carries out the rules of {@code robotworld.safety} (see the package documentation) with three background
 * threads, none of them on the path of a module call:
 * <ul>
 *   <li>{@code safety-link}: sends the program's {@link Heartbeat} into the space every heartbeat period, reads the
 *       heartbeats of the remote commanders of engaged actuators every {@value #POLL_MILLIS} ms, watches for stop
 *       requests, publishes stop records and answers (two threads, so a slow heartbeat does not hold up a
 *       poll);</li>
 *   <li>{@code safety-watch}: every {@value #CHECK_MILLIS} ms, stops actuators whose remote commander is silent or
 *       ended (rule 3) and, when the space has not been reached for an actuator's command timeout, stops every
 *       engaged actuator and holds it in its safe state until the space answers (rule 4; with
 *       {@code rwe.space.loss.stops=remote} only those a remote commander keeps engaged, without holding); it also
 *       carries out stop requests. It never waits for the network, only for the hardware.</li>
 * </ul>
 * Without a space (a program on its own hardware) only the clean-exit rule applies: {@link #stopAll}.
 *
 * <p>Thread-safe.
 */
public final class SafetySupervisor implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(SafetySupervisor.class);
    static final long POLL_MILLIS = 20;
    static final long CHECK_MILLIS = 10;
    /** The heartbeat and the last publications of a closing program wait at most this long for the space. */
    private static final long CLOSE_GRACE_MILLIS = 500;

    /** What is known of a remote commander's liveness, from its heartbeats. */
    private static final class Liveliness {
        volatile long sequence = Long.MIN_VALUE;
        /** When its heartbeat was last seen to change (0: not yet). */
        volatile long changedNanos;
        /** When its heartbeat was last read successfully. */
        volatile long checkedNanos;
        volatile boolean ended;
    }

    private final Capi space;
    private final String ownId;
    private final String host;
    private final SafetySettings settings;
    private final Duration heartbeatPeriod;
    private final ScheduledThreadPoolExecutor link;
    private final ScheduledThreadPoolExecutor watch;
    private final List<ActuatorGuard> guards = new CopyOnWriteArrayList<>();
    private final Set<Heartbeat.ModuleName> served = Collections.synchronizedSet(new LinkedHashSet<>());
    private final Map<String, ModuleSafety> described = new ConcurrentHashMap<>();
    /** The guards that losing the space stops and holds whoever commands them (rwe.space.loss.stops=all). */
    private final Set<ActuatorGuard> stoppedOnSpaceLossAlways = ConcurrentHashMap.newKeySet();
    private final Map<String, Liveliness> commanders = new ConcurrentHashMap<>();
    private final Set<String> handledRequests = Collections.synchronizedSet(new LinkedHashSet<>());
    private final AtomicLong sequence = new AtomicLong();
    /**
     * Held while a heartbeat is sent: the two link threads must not send two at once, or the older could reach the
     * space after the newer and replace it (a closing program's last heartbeat replaced by a periodic one that was
     * still under way, so the program would look silent instead of ended).
     */
    private final ReentrantLock sendingHeartbeat = new ReentrantLock();
    private final List<StopRecord> recent = new CopyOnWriteArrayList<>();
    private volatile Duration defaultCommandTimeout;
    private volatile long lastContactNanos = System.nanoTime();
    /** When the last heartbeat was begun; later than {@link #lastContactNanos} while one is under way or failed. */
    private volatile long attemptNanos;
    private volatile boolean spaceLost;
    /** Orders rule 4's stops and holds against the release when the space answers again. */
    private final Object spaceLossLock = new Object();
    private volatile ContainerRef liveness;
    private volatile Subscription stopRequests;
    private volatile boolean watching;
    private volatile boolean closed;
    private volatile boolean stoppedAll;
    private final List<java.util.concurrent.ScheduledFuture<?>> periodic = new CopyOnWriteArrayList<>();

    /**
     * @param space    the program's space, or null for a program on its own hardware
     * @param ownId    the program's id, {@code host#run}
     * @param host     the program's host name
     * @param settings where the settings come from
     */
    public SafetySupervisor(Capi space, String ownId, String host, SafetySettings settings) {
        this.space = space;
        this.ownId = Objects.requireNonNull(ownId, "ownId");
        this.host = Objects.requireNonNull(host, "host");
        this.settings = Objects.requireNonNull(settings, "settings");
        this.defaultCommandTimeout = settings.defaultCommandTimeout();
        this.heartbeatPeriod = space == null ? Duration.ZERO : settings.heartbeatPeriod();
        this.link = executor(space == null ? 1 : 2, "safety-link " + host);
        this.watch = executor(1, "safety-watch " + host);
        if (!heartbeatPeriod.isZero()) {
            // the first one here: it creates the liveness container and warms the connection up, so a cold start on
            // a busy machine is not taken for a lost space
            try {
                sendHeartbeat(false, Timeout.ofMillis(Math.max(1_000, heartbeatPeriod.toMillis() * 5)));
            } catch (SpaceException e) {
                LOG.warn("the first heartbeat of {} failed: {}", ownId, e.toString());
            }
            periodic.add(link.scheduleWithFixedDelay(this::beat, heartbeatPeriod.toMillis(), heartbeatPeriod.toMillis(),
                    TimeUnit.MILLISECONDS));
        }
    }

    /**
     * The program's space, as its proxies should use it: every answer of the space counts as contact for the rule
     * that stops actuators when the space is lost, so a busy program is never taken for a cut-off one.
     */
    public Capi tracking(Capi space) {
        return new ContactTrackingSpace(space, this::contact);
    }

    /** The program's id: {@code host#run}. */
    public String ownId() {
        return ownId;
    }

    /** The settings. */
    public SafetySettings settings() {
        return settings;
    }

    /** How often this program sends a heartbeat (zero: it does not). */
    public Duration heartbeatPeriod() {
        return heartbeatPeriod;
    }

    // ----- configuration -----

    /**
     * The description's safety values for a module; generated code calls this before it creates the module's
     * proxy. Run-time settings for the module still override them.
     */
    public void describe(String participant, String module, ModuleSafety safety) {
        described.put(key(participant, module), Objects.requireNonNull(safety, "safety"));
    }

    /** The description's safety values for a module ({@link ModuleSafety#NONE} when it gave none). */
    public ModuleSafety described(String participant, String module) {
        return described.getOrDefault(key(participant, module), ModuleSafety.NONE);
    }

    /** The command timeout for modules without one of their own ({@code rwe.command.timeout.ms}, else 500 ms). */
    public Duration defaultCommandTimeout() {
        return defaultCommandTimeout;
    }

    /** Sets the command timeout of actuators registered from now on (those without one of their own). */
    public void setDefaultCommandTimeout(Duration timeout) {
        defaultCommandTimeout = SafetySettings.checkCommandTimeout(timeout);
    }

    /** The command timeout a module gets: its setting, its description, the program's default. */
    public Duration commandTimeout(String participant, String module) {
        return settings.commandTimeout(participant, module, described(participant, module), defaultCommandTimeout);
    }

    /** The bus watchdog a module gets, in ms (0 = none); {@code typeDefault} as in {@link SafetySettings}. */
    public int watchdogMillis(String participant, String module, int typeDefault) {
        return settings.watchdogMillis(participant, module, described(participant, module), typeDefault);
    }

    /** What stopping does to an X10 module. */
    public X10SafeState x10SafeState(String participant, String module) {
        return settings.x10SafeState(participant, module, described(participant, module));
    }

    // ----- registration -----

    /** Notes that this program serves a module (sensor or actuator): it is named in heartbeats and stop answers. */
    public void serves(String participant, String module) {
        served.add(new Heartbeat.ModuleName(participant, module));
        startWatching();
    }

    /**
     * Guards an actuator this program serves, with the module's command timeout.
     *
     * @throws IllegalStateException when the program has ended
     */
    public ActuatorGuard guard(String participant, String module, Actuator actuator) {
        if (closed || stoppedAll) {
            throw new IllegalStateException("the program " + ownId + " has ended; it serves no new actuator");
        }
        ActuatorGuard guard = new ActuatorGuard(participant, module, actuator, ownId,
                commandTimeout(participant, module), this::stopped);
        if (settings.spaceLossStopsAll(participant, module)) {
            stoppedOnSpaceLossAlways.add(guard);
        }
        guards.add(guard);
        serves(participant, module);
        return guard;
    }

    /** Stops guarding an actuator (its proxy was closed); it is not stopped. */
    public void release(ActuatorGuard guard) {
        guards.remove(guard);
        stoppedOnSpaceLossAlways.remove(guard);
        served.remove(new Heartbeat.ModuleName(guard.participant(), guard.module()));
    }

    /** The guards, in registration order. */
    public List<ActuatorGuard> guards() {
        return List.copyOf(guards);
    }

    // ----- stopping -----

    /**
     * Puts every actuator of this program into its safe state now, in this thread, and (for a cause that
     * {@linkplain StopCause#endsTheProgram() ends the program}) refuses every later command. The clean-exit rule:
     * called when the program's runtime closes or its JVM shuts down.
     *
     * @return the stop records
     */
    public List<StopRecord> stopAll(StopCause cause, String reason) {
        if (cause.endsTheProgram()) {
            stoppedAll = true;
        }
        List<StopRecord> records = new ArrayList<>();
        for (ActuatorGuard guard : guards) {
            if (cause.endsTheProgram() && guard.hasEnded()) {
                continue; // stopped when the program began to end
            }
            records.add(guard.stop(cause, reason, null, null));
        }
        return records;
    }

    /**
     * A bus module's own watchdog tripped (its master heard of it afterwards): the module went to its safe state
     * by itself. The guard is stopped as well, so that its commanders are told on their next call.
     */
    public void watchdogTripped(String participant, String module, String detail) {
        for (ActuatorGuard guard : guards) {
            if (guard.participant().equals(participant) && guard.module().equals(module)) {
                watch.execute(() -> guard.stop(StopCause.WATCHDOG, detail, null, null));
            }
        }
    }

    /**
     * A bus module was found stopped by its own watchdog as this program armed it: the program that fed it before
     * died or went silent (a hard death, nobody else saw it). Recorded as a {@link StopCause#WATCHDOG} stop, logged
     * and published, so that monitors show it; its time is when it was found. Nobody is owed a notice: this
     * program has not commanded the module yet.
     */
    public void watchdogFoundTripped(String participant, String module, String detail) {
        stopped(new StopRecord(java.time.Instant.now(), participant, module, StopCause.WATCHDOG,
                detail + "; found when " + ownId + " armed it", "the module went to its safe state by itself",
                "its watchdog", null, null));
    }

    /** The stop records of this program, newest last (at most 100). */
    public List<StopRecord> recentStops() {
        return List.copyOf(recent);
    }

    /**
     * Ends the safety layer: puts every actuator into its safe state (if {@link #stopAll} was not called for the end
     * of the program yet), sends a last heartbeat saying the program ended, publishes what is left to publish
     * (each for at most half a second; the last heartbeat may first wait as long for one still under way), and stops
     * the threads. Idempotent.
     */
    public void close(StopCause cause, String reason) {
        if (closed) {
            return;
        }
        if (!stoppedAll) {
            stopAll(cause, reason);
        }
        closed = true;
        watch.shutdownNow();
        Subscription subscription = stopRequests;
        if (subscription != null) {
            subscription.cancel();
        }
        if (space != null) {
            periodic.forEach(task -> task.cancel(false)); // what is left are the publications of the stops
            try {
                link.execute(() -> {
                    try {
                        sendHeartbeat(true, Timeout.ofMillis(CLOSE_GRACE_MILLIS));
                    } catch (SpaceException e) {
                        LOG.debug("the last heartbeat of {} did not reach the space: {}", ownId, e.toString());
                    }
                });
                link.shutdown();
                // the last heartbeat may wait a grace for one under way, then take a grace of its own
                link.awaitTermination(3 * CLOSE_GRACE_MILLIS, TimeUnit.MILLISECONDS);
            } catch (java.util.concurrent.RejectedExecutionException e) {
                // already shut down
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        link.shutdownNow();
    }

    /** {@link #close(StopCause, String)} for a program that ended normally. */
    @Override
    public void close() {
        close(StopCause.PROGRAM_ENDED, "the program ended");
    }

    /** Whether {@link #close} was called. */
    public boolean isClosed() {
        return closed;
    }

    /** Logs and publishes one stop. */
    private void stopped(StopRecord record) {
        String line = record.where() + " " + record.summary();
        boolean expected = record.cause().endsTheProgram() || record.cause() == StopCause.STOP_REQUEST;
        if (record.action().startsWith("failed")) {
            LOG.error("{}", line);
        } else if (expected) {
            LOG.info("{}", line);
        } else {
            LOG.warn("{}", line);
        }
        recent.add(record);
        while (recent.size() > 100) {
            recent.remove(0);
        }
        publish(SafetyContainers.stopsSpec().name(), List.of(Item.of(record.toTuple())));
    }

    // ----- the link to the space -----

    /** How long serving a module waits for the stop-request watch to be in place before going on. */
    private static final long FIRST_SUBSCRIPTION_WAIT_MILLIS = 5_000;

    private volatile Future<?> subscribing;

    private void startWatching() {
        if (watching || space == null) {
            return;
        }
        synchronized (this) {
            if (watching || closed) {
                return;
            }
            watching = true;
            periodic.add(link.scheduleWithFixedDelay(this::poll, POLL_MILLIS, POLL_MILLIS, TimeUnit.MILLISECONDS));
            watch.scheduleWithFixedDelay(this::check, CHECK_MILLIS, CHECK_MILLIS, TimeUnit.MILLISECONDS);
            subscribing = link.submit(this::subscribeToStopRequests);
        }
        awaitFirstSubscription();
    }

    /**
     * Waits (a bounded time) until the stop-request watch is in place, so that a program serving a module hears a
     * {@code rwe stop} issued right after it started; a space that does not answer in time leaves the heartbeat
     * to subscribe later.
     */
    private void awaitFirstSubscription() {
        Future<?> first = subscribing;
        if (first == null) {
            return;
        }
        try {
            first.get(FIRST_SUBSCRIPTION_WAIT_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException | TimeoutException | CancellationException e) {
            LOG.debug("{}: the stop-request watch is not in place yet: {}", ownId, e.toString());
        }
    }

    private void beat() {
        try {
            sendHeartbeat(false, Timeout.ofMillis(Math.max(200, heartbeatPeriod.toMillis() * 5)));
            if (watching && (stopRequests == null || !stopRequests.isActive())) {
                subscribeToStopRequests();
            }
        } catch (SpaceException e) {
            LOG.debug("heartbeat of {} failed: {}", ownId, e.toString());
        } catch (RuntimeException e) { // the thread must not die: it is the program's sign of life
            LOG.warn("heartbeat of {} failed: {}", ownId, e.toString());
        }
    }

    private void sendHeartbeat(boolean ended, Timeout timeout) {
        boolean locked = false;
        try {
            // a heartbeat under way ends within its own timeout; the last one waits for it at most its own grace,
            // then goes anyway (readers also ignore a heartbeat older than one they have seen)
            locked = sendingHeartbeat.tryLock(timeout.millis(), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SpaceInterruptedException("interrupted before sending the heartbeat of " + ownId, e);
        }
        try {
            sendHeartbeatNow(ended, timeout);
        } finally {
            if (locked) {
                sendingHeartbeat.unlock();
            }
        }
    }

    private void sendHeartbeatNow(boolean ended, Timeout timeout) {
        List<Heartbeat.ModuleName> modules;
        synchronized (served) {
            modules = List.copyOf(served);
        }
        Heartbeat heartbeat = new Heartbeat(ownId, host, modules, ended, sequence.incrementAndGet(),
                heartbeatPeriod.toMillis(), System.currentTimeMillis());
        List<Item> items = List.of(Item.keyed(ownId, heartbeat.toTuple()));
        attemptNanos = System.nanoTime();
        try {
            space.shift(liveness(), timeout, items);
        } catch (ContainerNotFoundException gone) {
            liveness = null;
            space.shift(liveness(), timeout, items);
        }
        contact();
    }

    private ContainerRef liveness() {
        ContainerRef ref = liveness;
        if (ref == null) {
            ref = SafetyContainers.liveness(space);
            liveness = ref;
        }
        return ref;
    }

    /** The space answered: rule 4 starts counting again. */
    private void contact() {
        long now = System.nanoTime();
        if (now - lastContactNanos > 0) {
            lastContactNanos = now;
        }
        if (spaceLost) {
            synchronized (spaceLossLock) {
                if (!spaceLost) {
                    return;
                }
                spaceLost = false;
                guards.forEach(ActuatorGuard::release);
            }
            LOG.info("{} reaches its space {} again; stopped actuators stay stopped until commanded again", ownId,
                    space.spaceUri());
        }
    }

    /** Reads the heartbeats of the remote commanders that keep an actuator engaged. */
    private void poll() {
        Set<String> wanted = new LinkedHashSet<>();
        for (ActuatorGuard guard : guards) {
            if (guard.isEngaged()) {
                wanted.addAll(guard.remoteEngagers());
            }
        }
        commanders.keySet().retainAll(wanted);
        for (String commander : wanted) {
            try {
                List<Entry> found = space.read(liveness(), Timeout.TRY_ONCE, Selector.key(commander, Selector.ALL));
                long now = System.nanoTime();
                contact();
                Liveliness known = commanders.computeIfAbsent(commander, c -> new Liveliness());
                if (!found.isEmpty()) {
                    Heartbeat heartbeat = Heartbeat.parse(found.get(0));
                    if (known.sequence != Long.MIN_VALUE && heartbeat.sequence() != known.sequence) {
                        known.changedNanos = now;
                    }
                    known.sequence = heartbeat.sequence();
                    known.ended = heartbeat.ended();
                }
                known.checkedNanos = now;
            } catch (ContainerNotFoundException gone) {
                liveness = null;
            } catch (SpaceException e) {
                LOG.debug("reading the heartbeat of {} failed: {}", commander, e.toString());
                return;
            } catch (RuntimeException e) {
                LOG.warn("reading the heartbeat of {} failed: {}", commander, e.toString());
            }
        }
    }

    private void subscribeToStopRequests() {
        if (closed || space == null) {
            return;
        }
        try {
            ContainerRef container = SafetyContainers.stopRequests(space);
            stopRequests = space.subscribe(container, Set.of(Operation.WRITE, Operation.SHIFT),
                    NotificationMode.INFINITE, Timeout.INFINITE, new NotificationListener() {
                        @Override
                        public void onNotification(Notification notification) {
                            for (Entry entry : notification.entries()) {
                                try {
                                    StopRequest request = StopRequest.parse(entry);
                                    watch.execute(() -> handle(request));
                                } catch (IllegalArgumentException e) {
                                    LOG.warn("ignoring a malformed stop request: {}", e.getMessage());
                                } catch (java.util.concurrent.RejectedExecutionException closing) {
                                    return;
                                }
                            }
                        }

                        @Override
                        public void onEnd(SubscriptionEnd reason) {
                            LOG.debug("{}: watching stop requests ended ({}); watching again", ownId, reason);
                        }
                    });
        } catch (SpaceException e) {
            LOG.debug("{}: cannot watch stop requests yet: {}", ownId, e.toString());
        }
    }

    /** Pauses before the attempts to publish a stop record or answer: a busy space gets a few seconds. */
    private static final long[] PUBLISH_RETRY_MILLIS = {200, 1_000, 3_000};

    /**
     * Queues a shift of {@code items} into a safety container, on the link thread, never on a caller's path; an
     * attempt that fails is repeated a few times (a record that never arrives leaves a monitor without the reason of
     * a stop), while the program is closing only within the close's grace.
     */
    private void publish(String container, List<Item> items) {
        publish(container, items, 0);
    }

    private void publish(String container, List<Item> items, int attempt) {
        if (space == null || link.isShutdown()) {
            return;
        }
        Runnable shift = () -> {
            try {
                ContainerRef ref = switch (container) {
                    case SafetyContainers.STOPS -> SafetyContainers.stops(space);
                    case SafetyContainers.STOP_ANSWERS -> SafetyContainers.stopAnswers(space);
                    default -> throw new IllegalArgumentException(container);
                };
                space.shift(ref, Timeout.ofMillis(closed ? CLOSE_GRACE_MILLIS : 5_000), items);
            } catch (SpaceException e) {
                if (!closed && attempt < PUBLISH_RETRY_MILLIS.length) {
                    publish(container, items, attempt + 1);
                } else {
                    LOG.warn("{} could not publish {} entr(ies) into {}: {}", ownId, items.size(), container,
                            e.toString());
                }
            }
        };
        try {
            if (attempt == 0) {
                link.execute(shift);
            } else {
                link.schedule(shift, PUBLISH_RETRY_MILLIS[attempt - 1], TimeUnit.MILLISECONDS);
            }
        } catch (java.util.concurrent.RejectedExecutionException closing) {
            // the program has ended
        }
    }

    // ----- the rules -----

    /** Rules 3 and 4, on the watch thread. */
    private void check() {
        try {
            long now = System.nanoTime();
            long contact = lastContactNanos;
            long sinceContact = now - contact;
            // judged only while a heartbeat begun after the last contact is under way or has failed: a heartbeat
            // thread that simply did not get the CPU is no evidence of a lost space
            boolean overdue = attemptNanos - contact > 0;
            for (ActuatorGuard guard : guards) {
                if (guard.hasEnded()) {
                    continue;
                }
                long timeout = guard.commandTimeout().toNanos();
                if (!heartbeatPeriod.isZero() && overdue && sinceContact > timeout
                        && spaceLost(guard, contact, sinceContact)) {
                    continue;
                }
                if (guard.isEngaged() && guard.mayRetryStop()) {
                    checkCommanders(guard, timeout);
                }
            }
        } catch (RuntimeException e) { // the thread must survive anything the hardware throws
            LOG.error("safety check failed: {}", e.toString(), e);
        }
    }

    private void checkCommanders(ActuatorGuard guard, long timeout) {
        for (String commander : guard.remoteEngagers()) {
            Liveliness known = commanders.get(commander);
            long lastCommand = guard.lastCommandNanos(commander);
            if (known != null && known.ended && known.checkedNanos - lastCommand > 0) {
                guard.stop(StopCause.COMMANDER_ENDED, commander + " ended", commander, null);
                return;
            }
            long heard = Math.max(lastCommand, known == null ? 0 : known.changedNanos);
            // judged only on a heartbeat read after the deadline: a poll that is late is no evidence of silence
            long checked = known == null ? 0 : known.checkedNanos;
            if (checked - heard > timeout) {
                guard.stop(StopCause.COMMANDER_SILENT, commander + " silent for " + millis(checked - heard)
                        + " ms (command timeout " + guard.commandTimeout().toMillis() + " ms)", commander, null);
                return;
            }
        }
    }

    /**
     * Rule 4 for one actuator, whose command timeout the time since the last contact exceeds: stops it when it is
     * engaged and either it is stopped on every space loss or a remote commander keeps it engaged (their commands
     * went stale with the space); then holds it, when it is stopped on every space loss, until the space answers,
     * because nobody elsewhere could stop what its own program would start meanwhile.
     *
     * @param contact when the space last answered, as the check began: an answer since then cancels the rule
     * @return whether the rule applied (rule 3 need not be checked: no heartbeat can be read)
     */
    private boolean spaceLost(ActuatorGuard guard, long contact, long sinceContact) {
        synchronized (spaceLossLock) {
            // an answer that came in meanwhile has released the holds: holding again now would hold for nothing
            return lastContactNanos == contact && spaceLostForSure(guard, sinceContact);
        }
    }

    private boolean spaceLostForSure(ActuatorGuard guard, long sinceContact) {
        boolean always = stoppedOnSpaceLossAlways.contains(guard);
        String reason = "no contact with the space " + space.spaceUri() + " for " + millis(sinceContact)
                + " ms (command timeout " + guard.commandTimeout().toMillis() + " ms)";
        if (guard.isEngaged() && (always || !guard.remoteEngagers().isEmpty())) {
            if (!guard.mayRetryStop()) {
                return true;
            }
            sayLostOnce(sinceContact, always);
            guard.stop(StopCause.SPACE_LOST, reason, null, null, always);
            return true;
        }
        if (always && !guard.isHeld()) {
            sayLostOnce(sinceContact, true);
            guard.hold(new StopRecord(Instant.now(), guard.participant(), guard.module(), StopCause.SPACE_LOST,
                    reason, "held in its safe state", ownId, null, null));
        }
        return always;
    }

    private void sayLostOnce(long sinceContact, boolean holding) {
        if (!spaceLost) {
            spaceLost = true;
            LOG.warn("{} cannot reach its space {}: no contact for {} ms; {}", ownId, space.spaceUri(),
                    millis(sinceContact), holding ? "its actuators are stopped and take no command until it does"
                            : "the actuators commanded through it are stopped");
        }
    }

    /** Carries out a stop request, on the watch thread, and answers for every module this program serves. */
    private void handle(StopRequest request) {
        if (!handledRequests.add(request.id())) {
            return;
        }
        if (handledRequests.size() > 256) {
            synchronized (handledRequests) {
                handledRequests.remove(handledRequests.iterator().next());
            }
        }
        List<Item> answers = new ArrayList<>();
        Set<Heartbeat.ModuleName> actuators = new LinkedHashSet<>();
        String reason = "asked by " + request.from() + (request.reason().isEmpty() ? "" : ": " + request.reason());
        for (ActuatorGuard guard : guards) {
            if (!request.concerns(guard.participant())) {
                continue;
            }
            actuators.add(new Heartbeat.ModuleName(guard.participant(), guard.module()));
            StopRecord record = guard.stop(StopCause.STOP_REQUEST, reason, null, request.id());
            boolean failed = record.action().startsWith("failed");
            answers.add(Item.of(new StopAnswer(request.id(), guard.participant(), guard.module(), ownId,
                    failed ? StopAnswer.State.FAILED : StopAnswer.State.STOPPED, record.action()).toTuple()));
        }
        List<Heartbeat.ModuleName> modules;
        synchronized (served) {
            modules = List.copyOf(served);
        }
        for (Heartbeat.ModuleName module : modules) {
            if (request.concerns(module.participant()) && !actuators.contains(module)) {
                answers.add(Item.of(new StopAnswer(request.id(), module.participant(), module.module(), ownId,
                        StopAnswer.State.NO_ACTUATOR, "a sensor: nothing to stop").toTuple()));
            }
        }
        if (!answers.isEmpty()) {
            publish(SafetyContainers.STOP_ANSWERS, answers);
        }
    }

    // ----- helpers -----

    private static String key(String participant, String module) {
        return participant + "/" + module;
    }

    private static long millis(long nanos) {
        return TimeUnit.NANOSECONDS.toMillis(nanos);
    }

    private static ScheduledThreadPoolExecutor executor(int threads, String name) {
        ThreadFactory factory = task -> {
            Thread thread = new Thread(task, name);
            thread.setDaemon(true);
            return thread;
        };
        ScheduledThreadPoolExecutor executor = new ScheduledThreadPoolExecutor(threads, factory);
        executor.setExecuteExistingDelayedTasksAfterShutdownPolicy(false);
        executor.setRemoveOnCancelPolicy(true);
        return executor;
    }

    @Override
    public String toString() {
        return "SafetySupervisor[" + ownId + ", " + guards.size() + " actuator(s)]";
    }

    /** For tests: when the space last answered this program. */
    Instant lastContact() {
        return Instant.now().minusNanos(System.nanoTime() - lastContactNanos);
    }
}
