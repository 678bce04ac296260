package robotworld.observe;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.safety.Heartbeat;
import robotworld.safety.SafetyContainers;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.SpaceException;
import robotworld.space.Subscription;
import robotworld.space.SubscriptionEnd;
import robotworld.space.Timeout;
import robotworld.xvsm.CallTuple;
import robotworld.xvsm.MalformedCallException;

/**
 * Reads one world's traffic from a space and hands it to {@link WorldObserver}s (the contract is in the package
 * documentation). For every module it subscribes to the REQUEST container (requests written and taken: the queue
 * length, and when a call started) and the ANSWER container (answers, error answers, published local calls); for
 * every robot to its {@code GROUNDTRUTH} container; and to the programs' heartbeats
 * ({@value robotworld.safety.SafetyContainers#LIVENESS}), which tell whether the programs serving a participant run
 * ({@link Liveness}). Containers are looked up or created, so the tap may start before or after the programs it
 * watches; what the ANSWER and GROUNDTRUTH containers already hold is handed over first
 * ({@link AnswerSeen#earlier()}).
 *
 * <p>Notifications arrive on the space's threads and are queued (bounded: {@value #QUEUE_CAPACITY} events) for
 * the tap's dispatch thread, which calls the observers. So a slow observer never holds up the space's delivery;
 * if the queue is full, events are dropped and counted, and the observers get a {@link Gap}.
 *
 * <pre>{@code
 * try (WorldTap tap = new WorldTap(space, layout)) {
 *     tap.add(observer);
 *     tap.start();            // or startInBackground() on the Swing thread
 *     ...
 * }
 * }</pre>
 */
public final class WorldTap implements AutoCloseable {

    /**
     * Without heartbeats: how long without a sign of life in the traffic before a participant is no longer
     * {@link Liveness.State#ALIVE}, and how long a request may wait before it is {@link Liveness.State#NOT_ANSWERING}.
     */
    public static final Duration DEFAULT_LIVENESS_WINDOW = Duration.ofSeconds(3);
    /** Events that may wait for the dispatch thread before new ones are dropped. */
    public static final int QUEUE_CAPACITY = 20_000;

    private static final Logger LOG = LoggerFactory.getLogger(WorldTap.class);
    private static final Set<Operation> REQUEST_OPERATIONS = Set.of(Operation.WRITE, Operation.TAKE);
    private static final Set<Operation> PUBLISHING = Set.of(Operation.WRITE, Operation.SHIFT);
    /** Requests whose answer the tap still waits for, per module, to measure latency: bounded. */
    private static final int PENDING_LIMIT = 10_000;
    private static final long TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(250);

    private final Capi space;
    private final WorldLayout layout;
    private final long livenessWindowNanos;
    private final List<WorldObserver> observers = new CopyOnWriteArrayList<>();
    private final BlockingQueue<Runnable> inbox;
    private final AtomicLong dropped = new AtomicLong();
    private final List<Subscription> subscriptions = new ArrayList<>();
    private final CountDownLatch startAttempted = new CountDownLatch(1);
    private final Thread dispatcher;
    private volatile boolean watching;
    private volatile boolean closed;
    private boolean started;

    // ---- state of the dispatch thread only ----
    private final Map<ModuleRef, ModuleState> modules = new LinkedHashMap<>();
    private final Map<String, ParticipantState> participants = new LinkedHashMap<>();
    /** Filled by the space's delivery threads, judged by the dispatch thread (it is thread-safe). */
    private final ServingPrograms programs;
    private long lastTick = System.nanoTime();

    /** A tap of {@code layout}'s containers in {@code space}, with the default liveness window. */
    public WorldTap(Capi space, WorldLayout layout) {
        this(space, layout, DEFAULT_LIVENESS_WINDOW);
    }

    /** A tap of {@code layout}'s containers in {@code space}; it watches once started. */
    public WorldTap(Capi space, WorldLayout layout, Duration livenessWindow) {
        this(space, layout, livenessWindow, QUEUE_CAPACITY);
    }

    /** As above, with a queue of {@code capacity} events (tests make it small to see a {@link Gap}). */
    WorldTap(Capi space, WorldLayout layout, Duration livenessWindow, int capacity) {
        this.inbox = new ArrayBlockingQueue<>(capacity);
        this.space = Objects.requireNonNull(space, "space");
        this.layout = Objects.requireNonNull(layout, "layout");
        this.livenessWindowNanos = livenessWindow.toNanos();
        for (WorldLayout.Participant participant : layout.participants()) {
            participants.put(participant.name(), new ParticipantState(participant.name()));
            for (ModuleRef module : participant.modules()) {
                modules.put(module, new ModuleState(module));
            }
        }
        programs = new ServingPrograms(participants.keySet());
        dispatcher = new Thread(this::dispatch, "world-tap " + layout.world());
        dispatcher.setDaemon(true);
    }

    /** The world watched. */
    public WorldLayout layout() {
        return layout;
    }

    /** Adds an observer; add them before {@link #start()} to see what the containers already hold. */
    public WorldTap add(WorldObserver observer) {
        observers.add(Objects.requireNonNull(observer, "observer"));
        return this;
    }

    /** Removes an observer: no calls after the one under way, if any. */
    public void remove(WorldObserver observer) {
        observers.remove(observer);
    }

    /**
     * Starts watching on this thread: looks up or creates every container, hands over what they hold, and
     * subscribes. A module that cannot be watched gets a {@link Gap} with {@code ended}; the others are watched.
     *
     * @return this tap
     * @throws SpaceException the first failure, when some container could not be watched
     * @throws IllegalStateException when started before
     */
    public WorldTap start() {
        synchronized (this) {
            if (started) {
                throw new IllegalStateException("the tap was started before");
            }
            started = true;
        }
        dispatcher.start();
        SpaceException first = null;
        try {
            try {
                ReplayMark.find(space).ifPresent(mark -> post(() -> each(observer -> observer.replay(mark))));
            } catch (SpaceException e) {
                LOG.debug("cannot tell whether {} replays a recording: {}", layout.world(), e.getMessage());
            }
            for (ModuleRef module : modules.keySet()) {
                try {
                    watchModule(module);
                } catch (SpaceException e) {
                    first = first == null ? e : first;
                    post(() -> deliverGap(new Gap(Instant.now(), module, -1, "cannot watch " + module.answerContainer()
                            + ": " + e.getMessage(), true)));
                }
            }
            for (String robot : layout.robots().toList()) {
                try {
                    watchGroundTruth(robot);
                } catch (SpaceException e) {
                    first = first == null ? e : first;
                    post(() -> deliverGap(new Gap(Instant.now(), null, -1, "cannot watch "
                            + GroundTruthTuples.containerName(robot) + ": " + e.getMessage(), false)));
                }
            }
            try {
                watchHeartbeats();
            } catch (SpaceException e) {
                first = first == null ? e : first;
                post(() -> deliverGap(new Gap(Instant.now(), null, -1, "cannot watch " + SafetyContainers.LIVENESS
                        + " (liveness then rests on the traffic alone): " + e.getMessage(), false)));
            }
            watching = first == null && !closed;
        } finally {
            startAttempted.countDown();
        }
        if (first != null) {
            throw first;
        }
        return this;
    }

    /**
     * Starts on a background thread (for the Swing thread, which must not wait for the network); failures reach
     * the observers as {@link Gap}s.
     *
     * @return this tap
     */
    public WorldTap startInBackground() {
        Thread starter = new Thread(() -> {
            try {
                start();
            } catch (SpaceException e) {
                LOG.debug("tap of {} started with failures: {}", layout.world(), e.getMessage());
            } catch (RuntimeException e) {
                LOG.warn("tap of {} failed to start", layout.world(), e);
            }
        }, "world-tap-start " + layout.world());
        starter.setDaemon(true);
        starter.start();
        return this;
    }

    /**
     * Waits until the start has been tried.
     *
     * @return whether every container is watched (false: some start failed, or is still under way)
     */
    public boolean awaitWatching(Duration timeout) throws InterruptedException {
        return startAttempted.await(timeout.toMillis(), TimeUnit.MILLISECONDS) && watching;
    }

    /** Stops watching: cancels the subscriptions; no observer is called once this returns (but from itself). */
    @Override
    public void close() {
        List<Subscription> toCancel;
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            toCancel = new ArrayList<>(subscriptions);
            subscriptions.clear();
        }
        for (Subscription subscription : toCancel) {
            try {
                subscription.cancel();
            } catch (RuntimeException e) {
                LOG.debug("cancelling a subscription: {}", e.getMessage());
            }
        }
        dispatcher.interrupt();
        if (Thread.currentThread() != dispatcher && dispatcher.isAlive()) {
            try {
                dispatcher.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    // ---- watching (on the starting thread, and the space's delivery threads) ----

    private void watchModule(ModuleRef module) {
        ContainerRef requests = space.lookupOrCreateContainer(requestSpec(module));
        ContainerRef answers = space.lookupOrCreateContainer(answerSpec(module));
        int queued = space.describeContainer(requests).size();
        post(() -> modules.get(module).queueKnown(queued, System.nanoTime()));
        subscribe(requests, REQUEST_OPERATIONS, () -> requestSpec(module), new RequestListener(module), module);
        List<Entry> earlier = space.read(answers, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL));
        Instant now = Instant.now();
        for (Entry entry : earlier) {
            CallTuple answer = parse(module, entry);
            if (answer != null) {
                post(() -> modules.get(module).answer(answer, now, System.nanoTime(), true));
            }
        }
        subscribe(answers, PUBLISHING, () -> answerSpec(module), new AnswerListener(module), module);
    }

    private void watchGroundTruth(String robot) {
        ContainerSpec spec = GroundTruthTuples.containerSpec(robot);
        ContainerRef frames = space.lookupOrCreateContainer(spec);
        for (Entry entry : space.read(frames, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL))) {
            post(() -> deliverFrame(entry));
        }
        subscribe(frames, PUBLISHING, () -> spec, notification -> {
            for (Entry entry : notification.entries()) {
                post(() -> deliverFrame(entry));
            }
        }, null);
    }

    /**
     * The heartbeats every program shifts into {@value SafetyContainers#LIVENESS}: those already there (perhaps a
     * dead program's) count from now; each new one is a sign of life, noted on arrival so that a busy dispatch
     * thread does not make a running program look silent.
     */
    private void watchHeartbeats() {
        ContainerSpec spec = SafetyContainers.livenessSpec();
        ContainerRef container = space.lookupOrCreateContainer(spec);
        Instant now = Instant.now();
        long nanos = System.nanoTime();
        for (Entry entry : space.read(container, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL))) {
            heard(entry, now, nanos, false);
        }
        subscribe(container, PUBLISHING, () -> spec, notification -> {
            Instant at = Instant.now();
            long arrived = System.nanoTime();
            for (Entry entry : notification.entries()) {
                heard(entry, at, arrived, true);
            }
        }, null);
    }

    private void heard(Entry entry, Instant at, long nanos, boolean arrived) {
        try {
            programs.heard(Heartbeat.parse(entry), at, nanos, arrived);
        } catch (IllegalArgumentException e) {
            LOG.debug("ignoring an entry of {} that is not a heartbeat: {}", SafetyContainers.LIVENESS, entry);
        }
    }

    /** The spec the runtime creates a REQUEST container with: FIFO, unbounded. */
    static ContainerSpec requestSpec(ModuleRef module) {
        return ContainerSpec.of(Order.FIFO).unbounded().named(module.requestContainer());
    }

    /** The spec the runtime creates an ANSWER container with: LIFO with a KEY view, unbounded. */
    static ContainerSpec answerSpec(ModuleRef module) {
        return ContainerSpec.of(Order.LIFO).withKeyView().unbounded().named(module.answerContainer());
    }

    private void subscribe(ContainerRef container, Set<Operation> operations,
            java.util.function.Supplier<ContainerSpec> spec, NotificationListener listener, ModuleRef module) {
        synchronized (this) {
            if (closed) {
                return;
            }
            subscriptions.add(space.subscribe(container, operations, NotificationMode.INFINITE, Timeout.INFINITE,
                    new Renewing(operations, spec, listener, module)));
        }
    }

    /** Forwards notifications, and subscribes again when the space ended the subscription early. */
    private final class Renewing implements NotificationListener {
        private final Set<Operation> operations;
        private final java.util.function.Supplier<ContainerSpec> spec;
        private final NotificationListener listener;
        private final ModuleRef module;

        Renewing(Set<Operation> operations, java.util.function.Supplier<ContainerSpec> spec,
                NotificationListener listener, ModuleRef module) {
            this.operations = operations;
            this.spec = spec;
            this.listener = listener;
            this.module = module;
        }

        @Override
        public void onNotification(Notification notification) {
            listener.onNotification(notification);
        }

        @Override
        public void onEnd(SubscriptionEnd reason) {
            if (closed || reason == SubscriptionEnd.CANCELLED) {
                return;
            }
            String name = spec.get().name();
            if (reason == SubscriptionEnd.OVERFLOWED || reason == SubscriptionEnd.CONTAINER_DESTROYED) {
                try {
                    ContainerRef again = space.lookupOrCreateContainer(spec.get());
                    subscribe(again, operations, spec, listener, module);
                    post(() -> deliverGap(new Gap(Instant.now(), module, -1, name + ": "
                            + (reason == SubscriptionEnd.OVERFLOWED ? "the space dropped notifications"
                            : "the container was destroyed") + "; watching again", false)));
                    return;
                } catch (SpaceException e) {
                    post(() -> deliverGap(new Gap(Instant.now(), module, -1, "cannot watch " + name + " again: "
                            + e.getMessage(), true)));
                    return;
                }
            }
            String why = reason == SubscriptionEnd.SPACE_CLOSED ? "the space connection closed"
                    : "watching " + name + " ended: " + reason;
            post(() -> deliverGap(new Gap(Instant.now(), module, -1, why, true)));
        }
    }

    private final class RequestListener implements NotificationListener {
        private final ModuleRef module;

        RequestListener(ModuleRef module) {
            this.module = module;
        }

        @Override
        public void onNotification(Notification notification) {
            long nanos = System.nanoTime();
            Instant now = Instant.now();
            if (notification.operation() == Operation.TAKE) {
                int count = notification.entries().size();
                post(() -> modules.get(module).taken(count, now, nanos));
                return;
            }
            for (Entry entry : notification.entries()) {
                CallTuple request = parse(module, entry);
                if (request != null) {
                    post(() -> modules.get(module).request(request, now, nanos));
                }
            }
        }
    }

    private final class AnswerListener implements NotificationListener {
        private final ModuleRef module;

        AnswerListener(ModuleRef module) {
            this.module = module;
        }

        @Override
        public void onNotification(Notification notification) {
            long nanos = System.nanoTime();
            Instant now = Instant.now();
            for (Entry entry : notification.entries()) {
                CallTuple answer = parse(module, entry);
                if (answer != null) {
                    post(() -> modules.get(module).answer(answer, now, nanos, false));
                }
            }
        }
    }

    private static CallTuple parse(ModuleRef module, Entry entry) {
        try {
            return CallTuple.parse(entry);
        } catch (MalformedCallException e) {
            LOG.debug("{}: ignoring an entry that is not a call: {}", module.label(), entry);
            return null;
        }
    }

    /** Queues work for the dispatch thread; counts it as dropped when the queue is full. */
    private void post(Runnable event) {
        if (closed) {
            return;
        }
        if (!inbox.offer(event)) {
            dropped.incrementAndGet();
        }
    }

    // ---- the dispatch thread ----

    private void dispatch() {
        try {
            while (!closed) {
                Runnable event = inbox.poll(TICK_NANOS, TimeUnit.NANOSECONDS);
                long lost = dropped.getAndSet(0);
                if (lost > 0) {
                    deliverGap(new Gap(Instant.now(), null, lost, lost + " events dropped: the observers fell behind",
                            false));
                }
                if (event != null && !closed) {
                    event.run();
                }
                long now = System.nanoTime();
                if (now - lastTick >= TICK_NANOS) {
                    lastTick = now;
                    participants.values().forEach(participant -> participant.evaluate(now));
                }
            }
        } catch (InterruptedException e) {
            // closed
        }
    }

    private void each(java.util.function.Consumer<WorldObserver> call) {
        for (WorldObserver observer : observers) {
            if (closed) {
                return;
            }
            try {
                call.accept(observer);
            } catch (RuntimeException e) {
                LOG.warn("observer {} failed; it keeps getting events", observer, e);
            }
        }
    }

    private void deliverGap(Gap gap) {
        each(observer -> observer.gap(gap));
    }

    private void deliverFrame(Entry entry) {
        if (!GroundTruthTuples.isFrame(entry)) {
            return;
        }
        GroundTruth frame;
        try {
            frame = GroundTruthTuples.decode(entry);
        } catch (IllegalArgumentException e) {
            LOG.debug("ignoring a ground-truth entry: {}", e.getMessage());
            return;
        }
        each(observer -> observer.groundTruth(frame));
    }

    /** What the dispatch thread knows about one module. */
    private final class ModuleState {
        private final ModuleRef module;
        /** Request key to when the tap saw it, oldest first, bounded. */
        private final LinkedHashMap<String, Long> pending = new LinkedHashMap<>(16, 0.75f, false) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, Long> eldest) {
                return size() > PENDING_LIMIT;
            }
        };
        /** Keys answered before their request was seen (the space delivers each container on its own thread). */
        private final LinkedHashMap<String, Boolean> answeredEarly = new LinkedHashMap<>(16, 0.75f, false) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, Boolean> eldest) {
                return size() > 1_000;
            }
        };
        private final Set<Integer> moving = new HashSet<>();
        private int queued;
        /** Since when the oldest waiting request waits (nanos), or -1 when none waits. */
        private long waitingSince = -1;

        ModuleState(ModuleRef module) {
            this.module = module;
        }

        void queueKnown(int size, long nanos) {
            queued = Math.max(queued, size);
            if (queued > 0 && waitingSince < 0) {
                waitingSince = nanos;
            }
            tellQueue(Instant.now());
        }

        void request(CallTuple request, Instant at, long nanos) {
            queued++;
            if (waitingSince < 0) {
                waitingSince = nanos;
            }
            if (answeredEarly.remove(request.key()) == null) {
                pending.put(request.key(), nanos);
            }
            RequestSeen event = new RequestSeen(module, request, at, queued);
            each(observer -> observer.requestSeen(event));
            tellQueue(at);
        }

        void taken(int count, Instant at, long nanos) {
            queued = Math.max(0, queued - count);
            waitingSince = queued == 0 ? -1 : nanos;
            tellQueue(at);
        }

        private void tellQueue(Instant at) {
            QueueLength event = new QueueLength(module, queued, at);
            each(observer -> observer.queueLength(event));
        }

        void answer(CallTuple answer, Instant at, long nanos, boolean earlier) {
            Long asked = earlier ? null : pending.remove(answer.key());
            if (asked == null && !earlier && answer.key().indexOf('#') >= 0) {
                answeredEarly.put(answer.key(), Boolean.TRUE);
            }
            Duration latency = asked == null || nanos < asked ? null : Duration.ofNanos(nanos - asked);
            AnswerSeen event = new AnswerSeen(module, answer, at, earlier, latency, queued);
            if (!earlier) {
                participants.get(module.participant()).signOfLife(at, nanos);
            }
            each(observer -> observer.answerSeen(event));
            if (!earlier) {
                watchForStop(event);
            }
        }

        /** A motor module whose last moving channel was set to 0 has stopped. */
        private void watchForStop(AnswerSeen event) {
            CallTuple answer = event.answer();
            if (!module.moduleClass().equals("MotorModule") || event.isError() || answer.size() != 2
                    || !(answer.is("setMotor") || answer.is("setMotorQuiet"))) {
                return;
            }
            int channel;
            int speed;
            try {
                channel = answer.intAt(0);
                speed = answer.intAt(1);
            } catch (MalformedCallException e) {
                return;
            }
            if (speed != 0) {
                moving.add(channel);
            } else if (moving.remove(channel) && moving.isEmpty()) {
                ActuatorStopped stopped = new ActuatorStopped(module, event.at(), event.host());
                each(observer -> observer.actuatorStopped(stopped));
            }
        }
    }

    /**
     * What the dispatch thread knows about one participant's liveness. Heartbeats come first: they tell a silent
     * (killed, frozen, cut off) or ended program apart from an idle one. Without them, the traffic tells what it can.
     */
    private final class ParticipantState {
        private final String name;
        private Instant lastSign;
        private long lastSignNanos;
        private Liveness.State state;

        ParticipantState(String name) {
            this.name = name;
        }

        void signOfLife(Instant at, long nanos) {
            lastSign = at;
            lastSignNanos = nanos;
            evaluate(nanos);
        }

        void evaluate(long now) {
            long oldestWait = -1;
            for (ModuleState module : modules.values()) {
                if (module.module.participant().equals(name) && module.waitingSince >= 0
                        && (oldestWait < 0 || module.waitingSince < oldestWait)) {
                    oldestWait = module.waitingSince;
                }
            }
            ServingPrograms.Verdict heartbeats = programs.verdict(name, now);
            Liveness.State next;
            String basis;
            Instant sign = lastSign;
            if (heartbeats != null && heartbeats.state() != Liveness.State.ALIVE && !answeredSince(heartbeats)) {
                next = heartbeats.state();
                basis = heartbeats.basis();
                sign = later(lastSign, heartbeats.lastSign());
            } else if (oldestWait >= 0 && now - oldestWait > livenessWindowNanos) {
                next = Liveness.State.NOT_ANSWERING;
                basis = "a request has waited " + (now - oldestWait) / 1_000_000_000L + " s";
            } else if (heartbeats != null && heartbeats.state() == Liveness.State.ALIVE) {
                next = Liveness.State.ALIVE;
                basis = heartbeats.basis();
                sign = later(lastSign, heartbeats.lastSign());
            } else if (lastSign != null && now - lastSignNanos <= livenessWindowNanos) {
                next = Liveness.State.ALIVE;
                basis = "answers";
            } else {
                next = Liveness.State.UNKNOWN;
                basis = lastSign == null ? "no heartbeat and no answer seen yet" : "quiet";
            }
            if (next != state) {
                state = next;
                Liveness event = new Liveness(name, next, sign, basis);
                each(observer -> observer.liveness(event));
            }
        }

        /**
         * Whether its modules kept answering well after the program of the heartbeats fell silent or ended: then
         * another program serves them, one without heartbeats, and the traffic is believed.
         */
        private boolean answeredSince(ServingPrograms.Verdict heartbeats) {
            return lastSign != null
                    && lastSignNanos - heartbeats.heardNanos() > ServingPrograms.LEAST_SILENCE.toNanos();
        }

        private static Instant later(Instant a, Instant b) {
            return a == null ? b : b == null || a.isAfter(b) ? a : b;
        }
    }
}
