package robotworld.cluster;

import java.lang.System.Logger.Level;
import java.net.URI;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentMap;
import java.util.concurrent.ConcurrentSkipListSet;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;

import com.hazelcast.cluster.Member;
import com.hazelcast.cluster.MembershipEvent;
import com.hazelcast.cluster.MembershipListener;
import com.hazelcast.core.DistributedObject;
import com.hazelcast.core.HazelcastException;
import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.core.HazelcastInstanceNotActiveException;
import com.hazelcast.core.MemberLeftException;
import com.hazelcast.core.OperationTimeoutException;
import com.hazelcast.map.IMap;
import com.hazelcast.spi.exception.RetryableException;
import com.hazelcast.spi.exception.TargetDisconnectedException;
import com.hazelcast.topic.ITopic;
import com.hazelcast.splitbrainprotection.SplitBrainProtectionException;

import robotworld.space.SpaceException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.internal.Delivery;

/**
 * What one member does for the space handles opened on it: it numbers their calls, runs them on the owning
 * members within their deadlines (repeating what may be repeated), passes each call's effects on to the members
 * concerned ({@link MemberMessage}), wakes the threads of served operations, feeds the subscriptions' inboxes,
 * and, when a member leaves, makes sure nothing waits for it and nothing it held is lost.
 */
final class ClusterNode {

    private static final System.Logger LOG = System.getLogger(ClusterNode.class.getName());
    private static final String KEY = ClusterNode.class.getName();
    /** How long a waiting thread sleeps at most before it looks at its container anyway. */
    static final long LONGEST_NAP_NANOS = TimeUnit.SECONDS.toNanos(5);
    static final long FIRST_NAP_NANOS = TimeUnit.SECONDS.toNanos(1);
    /** A cluster call slower than this is logged at DEBUG. */
    static final long SLOW_CALL_MILLIS = 400;
    /** How often every inbox checks its chain against its container's journal, in case a message was lost. */
    private static final long INBOX_CHECK_MILLIS = 5_000;
    /** How often a member makes the containers it owns put back held removals whose lease ran out. */
    private static final long SWEEP_MILLIS = 1_000;
    /** How long a departed member's operations are still looked for by the sweeps. */
    private static final long DEPARTED_KEPT_NANOS = TimeUnit.MINUTES.toNanos(5);

    private final HazelcastInstance hazelcast;
    private final ClusterOptions options;
    /** This member's id; it changes when the member rejoins after a split healed. */
    private volatile UUID self;
    private final String idTag;
    private final AtomicLong counter = new AtomicLong();
    private final ConcurrentSkipListSet<Long> inFlight = new ConcurrentSkipListSet<>();
    private final ConcurrentMap<OpId, LocalWaiter> waiters = new ConcurrentHashMap<>();
    /** Members that left lately, with when: the owners' sweeps forget operations of theirs that arrived late. */
    private final ConcurrentMap<UUID, Long> departed = new ConcurrentHashMap<>();
    private final ConcurrentMap<String, EventInbox> inboxes = new ConcurrentHashMap<>();
    private final ConcurrentMap<String, Long> staleChecks = new ConcurrentHashMap<>();
    /** Registration of this member's listener on its own topic. */
    private volatile UUID topicRegistration;
    /**
     * Timers only: every task it fires runs on {@link #maintenance}. Its threads never make a cluster call, because
     * a call can block for seconds while the cluster recovers from a member's failure (the moment the timers are
     * needed most): the waits' deadlines and looks would then fire late.
     */
    private final ScheduledThreadPoolExecutor background;
    /** Work in the background that calls the cluster: members leaving, sweeps, inbox repairs, timed-out waits. */
    private final java.util.concurrent.ExecutorService maintenance;
    private final java.util.concurrent.atomic.AtomicBoolean checkingInboxes = new java.util.concurrent.atomic.AtomicBoolean();
    private final java.util.concurrent.atomic.AtomicBoolean sweepingReceipts = new java.util.concurrent.atomic.AtomicBoolean();
    /** Steps of operations that wait without a thread (collect a result, withdraw, queue again). */
    private final java.util.concurrent.ExecutorService steps;
    private final Delivery delivery;
    private final UUID membershipRegistration;
    private volatile boolean closed;

    ClusterNode(HazelcastInstance hazelcast, ClusterOptions options) {
        this.hazelcast = hazelcast;
        this.options = options;
        this.self = hazelcast.getCluster().getLocalMember().getUuid();
        this.idTag = Long.toString(self.getLeastSignificantBits() >>> 1, 36);
        AtomicInteger threads = new AtomicInteger();
        this.background = new ScheduledThreadPoolExecutor(2, task -> {
            Thread thread = new Thread(task, "space-cluster-" + threads.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        });
        background.setRemoveOnCancelPolicy(true);
        AtomicInteger workThreads = new AtomicInteger();
        this.maintenance = java.util.concurrent.Executors.newCachedThreadPool(task -> {
            Thread thread = new Thread(task, "space-cluster-work-" + workThreads.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        });
        AtomicInteger stepThreads = new AtomicInteger();
        this.steps = java.util.concurrent.Executors.newCachedThreadPool(task -> {
            Thread thread = new Thread(task, "space-cluster-wait-" + stepThreads.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        });
        this.delivery = new Delivery("space-cluster");
        hazelcast.getUserContext().put(KEY, this);
        listenToOwnTopic();
        this.membershipRegistration = hazelcast.getCluster().addMembershipListener(new MembershipListener() {
            @Override
            public void memberAdded(MembershipEvent event) {
                departed.remove(event.getMember().getUuid()); // back under the same id: not departed
            }

            @Override
            public void memberRemoved(MembershipEvent event) {
                runInBackground(() -> memberLeft(event.getMember()));
            }
        });
        hazelcast.getLifecycleService().addLifecycleListener(event -> {
            if (event.getState() == com.hazelcast.core.LifecycleEvent.LifecycleState.MERGED) {
                runInBackground(this::rejoined);
            }
        });
        background.scheduleWithFixedDelay(() -> runUnlessRunning(checkingInboxes, this::checkInboxes),
                INBOX_CHECK_MILLIS, INBOX_CHECK_MILLIS, TimeUnit.MILLISECONDS);
        background.scheduleWithFixedDelay(() -> runUnlessRunning(sweepingReceipts, this::sweepReceipts),
                SWEEP_MILLIS, SWEEP_MILLIS, TimeUnit.MILLISECONDS);
    }

    /** The node of a running member, or null. */
    static ClusterNode of(HazelcastInstance hazelcast) {
        return (ClusterNode) hazelcast.getUserContext().get(KEY);
    }

    /**
     * Messages to this member come on its own topic: a published message goes straight to the one member that
     * listens, without an answer (cheaper than a task on an executor).
     */
    private void listenToOwnTopic() {
        ITopic<MemberMessage> topic = hazelcast.getTopic(HazelcastSetup.MEMBER_TOPIC + self);
        topicRegistration = topic.addMessageListener(message -> receive(message.getMessageObject()));
    }

    HazelcastInstance hazelcast() {
        return hazelcast;
    }

    ClusterOptions options() {
        return options;
    }

    UUID self() {
        return self;
    }

    Delivery delivery() {
        return delivery;
    }

    boolean isClosed() {
        return closed;
    }

    IMap<String, ContainerRecord> containers(String space) {
        return hazelcast.getMap(HazelcastSetup.CONTAINERS + space);
    }

    IMap<String, NameRecord> names(String space) {
        return hazelcast.getMap(HazelcastSetup.NAMES + space);
    }

    /** A container id no other container of this cluster ever had: a number of this member and its tag. */
    String newContainerId() {
        return "c" + Long.toString(counter.incrementAndGet(), 36) + "-" + idTag;
    }

    // ---- call ids ----

    /** A new call id; the call counts as in progress until {@link #end}. */
    OpId begin() {
        long number = counter.incrementAndGet();
        inFlight.add(number);
        return new OpId(self, number);
    }

    void end(OpId call) {
        if (call != null) {
            inFlight.remove(call.counter());
        }
    }

    /** This member's oldest call still in progress: the containers may forget the outcomes of older ones. */
    private long lowWater() {
        try {
            return inFlight.first();
        } catch (java.util.NoSuchElementException none) {
            return counter.get() + 1;
        }
    }

    // ---- running calls ----

    /**
     * Runs {@code call} on its container's owner and passes its effects on. Failures that Hazelcast reports as
     * worth repeating (the owner died, partitions move, too few members, no answer) are repeated with the same call
     * id (so at most once in effect) until {@code deadline} ({@link System#nanoTime()}); then
     * {@link SpaceUnavailableException}. Each attempt waits at most Hazelcast's call timeout, which is the call
     * allowance ({@link HazelcastSetup}).
     *
     * <p>Calls are synchronous on purpose: Hazelcast's asynchronous map calls complete through a dependent stage
     * that, on a computer with two cores, starts a new thread for every call.
     */
    Outcome call(String space, String container, ContainerCall call, long deadline, URI uri) {
        // the map is looked up inside the retried call: on a member that is no longer active the lookup itself
        // fails, and that must read as the member gone (its server's clients move on), not as an internal error
        Outcome outcome = retrying(() -> containers(space).executeOnKey(container, call.lowWater(lowWater())),
                deadline, uri, call.kind() + " on " + container);
        dispatch(space, container, outcome);
        return outcome;
    }

    /** Runs a naming call within {@code deadline}, repeating it as {@link #call} does. */
    NameRecord nameCall(String space, String name, NameCall call, long deadline, URI uri) {
        return retrying(() -> names(space).executeOnKey(name, call), deadline, uri, "naming '" + name + "'");
    }

    NameRecord lookupName(String space, String name, long deadline, URI uri) {
        return retrying(() -> names(space).get(name), deadline, uri, "lookup of '" + name + "'");
    }

    /** How often a call was looked for in every container ({@link #findReceipt}): costly, rare when clients name containers. */
    final java.util.concurrent.atomic.LongAdder receiptSearches = new java.util.concurrent.atomic.LongAdder();

    /** The container of space {@code space} that knows client call {@code callId}, asking all of them; or null. */
    String findReceipt(String space, String callId, long deadline, URI uri) {
        receiptSearches.increment();
        Map<String, Outcome> answers = retrying(() -> containers(space).executeOnEntries(
                ContainerCall.receipts(ContainerCall.Kind.FIND_RECEIPTS, null, List.of(callId))), deadline, uri,
                "looking for call " + callId);
        for (Map.Entry<String, Outcome> answer : answers.entrySet()) {
            if (answer.getValue() != null && !answer.getValue().calls.isEmpty()) {
                return answer.getKey();
            }
        }
        return null;
    }

    void createRecord(String space, ContainerRecord record, long deadline, URI uri) {
        retrying(() -> {
            containers(space).set(record.id(), record);
            return null;
        }, deadline, uri, "creating " + record.id());
    }

    void deleteRecord(String space, String id, long deadline, URI uri) {
        retrying(() -> {
            containers(space).delete(id);
            return null;
        }, deadline, uri, "deleting " + id);
    }

    private <T> T retrying(Supplier<T> invocation, long deadline, URI uri, String what) {
        long pause = TimeUnit.MILLISECONDS.toNanos(20);
        boolean interrupted = false;
        long started = System.nanoTime();
        int attempts = 0;
        Throwable failure = null;
        try {
            while (true) {
                if (closed) {
                    throw memberGone(uri);
                }
                attempts++;
                try {
                    return invocation.get(); // Hazelcast's synchronous calls are not interruptible
                } catch (RuntimeException e) {
                    failure = e instanceof HazelcastException && e.getCause() instanceof ExecutionException
                            ? e.getCause().getCause() : e;
                }
                if (failure instanceof HazelcastInstanceNotActiveException) {
                    throw memberGone(uri);
                }
                if (!isWorthRepeating(failure)) {
                    throw failure instanceof SpaceException space ? space
                            : new SpaceException("cluster call failed: " + what + ": " + failure, failure);
                }
                if (System.nanoTime() + pause - deadline > 0) {
                    throw unavailable(uri, what, failure);
                }
                try {
                    TimeUnit.NANOSECONDS.sleep(pause);
                } catch (InterruptedException e) {
                    interrupted = true;
                }
                pause = Math.min(pause * 2, TimeUnit.MILLISECONDS.toNanos(250));
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
            logIfSlow(what, started, attempts, failure);
        }
    }

    /**
     * At DEBUG, a cluster call that took longer than {@link #SLOW_CALL_MILLIS}: how long, how many attempts, what
     * the last attempt failed with. What a member's log shows when calls stall after another member's loss.
     */
    private static void logIfSlow(String what, long started, int attempts, Throwable lastFailure) {
        long millis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
        if (millis > SLOW_CALL_MILLIS && LOG.isLoggable(Level.DEBUG)) {
            LOG.log(Level.DEBUG, "slow cluster call: " + what + " took " + millis + " ms in " + attempts
                    + (attempts == 1 ? " attempt" : " attempts") + (lastFailure == null ? ""
                    : ", the last failure being " + lastFailure));
        }
    }

    /** This member has shut down: for the space, unreachable through it (another member may serve). */
    static SpaceUnavailableException memberGone(URI uri) {
        return new SpaceUnavailableException(uri, "this cluster member has shut down", null);
    }

    private SpaceUnavailableException unavailable(URI uri, String what, Throwable failure) {
        if (failure instanceof SplitBrainProtectionException) {
            return new SpaceUnavailableException(uri, "too few cluster members can reach each other (at least "
                    + options.effectiveMinimumMembers() + " needed) for " + what, failure);
        }
        if (failure instanceof OperationTimeoutException) {
            return new SpaceUnavailableException(uri, "the cluster did not answer " + what + " in time; its outcome"
                    + " is unknown", failure);
        }
        return new SpaceUnavailableException(uri, "the cluster could not complete " + what + ": " + failure,
                failure);
    }

    private static boolean isWorthRepeating(Throwable failure) {
        return failure instanceof RetryableException
                || failure instanceof MemberLeftException
                || failure instanceof TargetDisconnectedException
                || failure instanceof OperationTimeoutException
                || failure instanceof SplitBrainProtectionException
                || (failure instanceof HazelcastException && failure.getCause() instanceof java.io.IOException);
    }

    // ---- effects: wake-ups and events for other members ----

    /** For tests: wake-ups are not passed on, as when the member that served an operation died first. */
    volatile boolean dropWakeUps;
    /** For tests: events are not passed on (as if still on their way to the members with subscriptions). */
    volatile boolean dropEvents;

    /** Passes a call's effects to the members concerned: wake-ups to waiting threads, events to subscriptions. */
    void dispatch(String space, String container, Outcome outcome) {
        if (!outcome.hasEffects()) {
            return;
        }
        Map<UUID, List<OpId>> wakes = new HashMap<>();
        for (OpId wake : dropWakeUps ? List.<OpId>of() : outcome.wakes) {
            wakes.computeIfAbsent(wake.member(), member -> new ArrayList<>()).add(wake);
        }
        Set<UUID> targets = new java.util.HashSet<>(wakes.keySet());
        if (!dropEvents) {
            targets.addAll(outcome.eventMembers);
        }
        for (UUID member : targets) {
            MemberMessage message = new MemberMessage(space, container, wakes.getOrDefault(member, List.of()),
                    !dropEvents && outcome.eventMembers.contains(member) ? outcome.events : List.of());
            if (member.equals(self)) {
                receive(message);
            } else {
                send(member, message);
            }
        }
    }

    private void send(UUID member, MemberMessage message) {
        try {
            hazelcast.<MemberMessage>getTopic(HazelcastSetup.MEMBER_TOPIC + member).publish(message);
        } catch (RuntimeException e) {
            // the member is leaving (its waiters and subscriptions are forgotten with it), or this one is
            LOG.log(Level.DEBUG, "could not pass effects to member " + member + ": " + e);
        }
    }

    /** Effects another member (or this one) passed on. */
    void receive(MemberMessage message) {
        for (OpId wake : message.wakes()) {
            LocalWaiter waiter = waiters.get(wake);
            if (waiter != null) {
                waiter.wake();
            } else {
                // nobody waits for it any more (its call gave up): put back what it took
                runInBackground(() -> undoAbandoned(message.space(), message.container(), wake));
            }
        }
        if (!message.events().isEmpty()) {
            EventInbox inbox = inboxes.get(inboxKey(message.space(), message.container()));
            if (inbox != null) {
                inbox.receive(message.events());
            } else {
                dropStaleSubscriptions(message.space(), message.container());
            }
        }
    }

    /**
     * Events came for a container on which this member has no subscription any more: late events of one just
     * ended, or a registration whose answer was lost. Asks the container (at most once a second) to drop this
     * member's subscriptions that no inbox here knows.
     */
    private void dropStaleSubscriptions(String space, String container) {
        String key = inboxKey(space, container);
        long now = System.nanoTime();
        Long last = staleChecks.get(key);
        if (last != null && now - last < TimeUnit.SECONDS.toNanos(1)) {
            return;
        }
        staleChecks.put(key, now);
        runInBackground(() -> {
            // a subscription made from now on gets a higher number (its inbox comes first, then its number)
            long below = counter.get() + 1;
            if (inboxes.containsKey(key)) {
                return; // a subscription is being made or is active meanwhile
            }
            OpId call = begin();
            try {
                call(space, container, ContainerCall.unsubscribeOlder(call, below),
                        deadlineIn(options.callAllowance().toMillis()), URI.create("cluster:" + space));
            } catch (SpaceException e) {
                LOG.log(Level.DEBUG, "could not drop stale subscriptions on " + container + ": " + e.getMessage());
            } finally {
                end(call);
                staleChecks.remove(key);
            }
        });
    }

    private void undoAbandoned(String space, String container, OpId waiter) {
        OpId call = begin();
        try {
            call(space, container, ContainerCall.about(ContainerCall.Kind.WITHDRAW_AND_UNDO, call, waiter),
                    deadlineIn(options.callAllowance().toMillis() * 4), URI.create("cluster:" + space));
        } catch (SpaceException e) {
            LOG.log(Level.WARNING, "could not return the result of abandoned operation " + waiter + " on "
                    + container + "; the container undoes it after "
                    + ContainerRules.UNCOLLECTED_AFTER_MILLIS / 1000 + " s: " + e.getMessage());
        } finally {
            end(call);
        }
    }

    // ---- waiters and inboxes of this member ----

    LocalWaiter register(OpId call) {
        return register(new LocalWaiter(call));
    }

    LocalWaiter register(LocalWaiter waiter) {
        waiters.put(waiter.id(), waiter);
        return waiter;
    }

    /**
     * Runs a step of an operation that waits without a thread (it makes calls to the cluster, so never on a
     * Hazelcast thread): threads are made as needed and end when idle.
     */
    void runStep(Runnable step) {
        try {
            steps.execute(() -> {
                try {
                    step.run();
                } catch (RuntimeException e) {
                    LOG.log(Level.WARNING, "a waiting operation's step failed", e);
                }
            });
        } catch (RejectedExecutionException closing) {
            // the member is shutting down; its handles end their operations
        }
    }

    void unregister(LocalWaiter waiter) {
        waiters.remove(waiter.id(), waiter);
    }

    EventInbox inbox(String space, String container, java.util.function.Function<String, EventInbox> create) {
        return inboxes.computeIfAbsent(inboxKey(space, container), create);
    }

    void removeInbox(String space, String container, EventInbox inbox) {
        inboxes.remove(inboxKey(space, container), inbox);
    }

    private static String inboxKey(String space, String container) {
        return space + '\u0000' + container;
    }

    /** A periodic task: runs in the background, and is skipped while its previous run still goes on. */
    private void runUnlessRunning(java.util.concurrent.atomic.AtomicBoolean running, Runnable task) {
        if (running.compareAndSet(false, true)) {
            runInBackground(() -> {
                try {
                    task.run();
                } finally {
                    running.set(false);
                }
            });
        }
    }

    /** Runs {@code task}, which may call the cluster, on a background thread. */
    void runInBackground(Runnable task) {
        try {
            maintenance.execute(() -> {
                try {
                    task.run();
                } catch (RuntimeException e) {
                    LOG.log(Level.WARNING, "background task of the cluster space failed", e);
                }
            });
        } catch (RejectedExecutionException closing) {
            // the member is shutting down
        }
    }

    /**
     * Runs {@code task} (which may call the cluster) in the background after {@code delayMillis}; the handle cancels
     * it (null if the member is closing).
     */
    java.util.concurrent.ScheduledFuture<?> schedule(Runnable task, long delayMillis) {
        try {
            return background.schedule(() -> runInBackground(task), delayMillis, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException closing) {
            return null; // the member is shutting down
        }
    }

    /**
     * Held removals come back when their lease runs out at the next call on their container; for containers that
     * nobody calls, each member asks the containers it owns now and then (a call that changes nothing costs no
     * backup).
     */
    private void sweepReceipts() {
        if (closed) {
            return;
        }
        // a departed member's late operations can only have been sent before it died: minutes are plenty
        departed.values().removeIf(at -> System.nanoTime() - at > DEPARTED_KEPT_NANOS);
        Set<UUID> gone = Set.copyOf(departed.keySet());
        try {
            for (DistributedObject object : hazelcast.getDistributedObjects()) {
                if (object instanceof IMap<?, ?> && object.getName().startsWith(HazelcastSetup.CONTAINERS)) {
                    String space = object.getName().substring(HazelcastSetup.CONTAINERS.length());
                    IMap<String, ContainerRecord> map = containers(space);
                    for (String container : map.localKeySet()) {
                        // entries that come back may serve waiting operations: their wake-ups are passed on
                        dispatch(space, container, map.executeOnKey(container, ContainerCall.sweep(gone)));
                    }
                }
            }
        } catch (RuntimeException e) {
            LOG.log(Level.DEBUG, "receipt sweep skipped: " + e);
        }
    }

    private void checkInboxes() {
        for (EventInbox inbox : inboxes.values()) {
            inbox.repair();
        }
    }

    // ---- members leaving ----

    /**
     * A member left. The oldest remaining member clears what the departed held in every container (queued
     * operations, subscriptions, uncollected results, which are put back); every member then looks at its own
     * waiting operations and event chains at once, since the departed may have served them without passing the
     * news on.
     */
    private void memberLeft(Member departed) {
        if (closed) {
            return;
        }
        LOG.log(Level.INFO, "cluster member " + departed.getAddress() + " left");
        this.departed.put(departed.getUuid(), System.nanoTime());
        wakeWaiters(); // at once: the departed may have served them without passing the news on
        if (isOldest()) {
            forgetDeparted(); // may serve operations again (their wake-ups are passed on as any call's)
        }
        checkInboxes();
    }

    /** Every waiting operation of this member looks at where it stands. */
    void wakeWaiters() {
        for (LocalWaiter waiter : waiters.values()) {
            waiter.wake();
        }
    }

    /**
     * This member was cut off and has merged back into the larger side, which forgot it meanwhile: it takes its new
     * id, and its waiting threads and subscriptions check where they stand (a forgotten operation is queued again,
     * a subscription that may have missed events ends with a gap signal).
     */
    private void rejoined() {
        UUID old = self;
        self = hazelcast.getCluster().getLocalMember().getUuid();
        if (!self.equals(old)) {
            hazelcast.getTopic(HazelcastSetup.MEMBER_TOPIC + old).removeMessageListener(topicRegistration);
            listenToOwnTopic();
        }
        LOG.log(Level.WARNING, "this member rejoined the cluster after a split; it now has id " + self);
        for (LocalWaiter waiter : waiters.values()) {
            waiter.wake();
        }
        checkInboxes();
    }

    private boolean isOldest() {
        return hazelcast.getCluster().getMembers().iterator().next().localMember();
    }

    private void forgetDeparted() {
        Set<UUID> live = new java.util.HashSet<>();
        for (Member member : hazelcast.getCluster().getMembers()) {
            live.add(member.getUuid());
        }
        for (DistributedObject object : hazelcast.getDistributedObjects()) {
            if (!(object instanceof IMap<?, ?>) || !object.getName().startsWith(HazelcastSetup.CONTAINERS)) {
                continue;
            }
            String space = object.getName().substring(HazelcastSetup.CONTAINERS.length());
            IMap<String, ContainerRecord> map = containers(space);
            Set<String> keys;
            try {
                keys = map.keySet();
            } catch (RuntimeException e) {
                LOG.log(Level.WARNING, "could not list the containers of space " + space + " to clear departed "
                        + "members; their uncollected results return after "
                        + ContainerRules.UNCOLLECTED_AFTER_MILLIS / 1000 + " s: " + e);
                continue;
            }
            // one call per container: its changes replicate like any call's
            for (String container : keys) {
                try {
                    call(space, container, ContainerCall.forgetMembers(live),
                            deadlineIn(options.callAllowance().toMillis() * 4), URI.create("cluster:" + space));
                } catch (SpaceException e) {
                    LOG.log(Level.WARNING, "could not clear departed members from " + container + ": "
                            + e.getMessage());
                }
            }
        }
    }

    static long deadlineIn(long millis) {
        return System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
    }

    // ---- shutdown ----

    /** Stops this member's part: waiting threads and subscriptions of its handles end (they are closed first). */
    void close() {
        closed = true;
        for (LocalWaiter waiter : waiters.values()) {
            waiter.close();
        }
        try {
            hazelcast.getCluster().removeMembershipListener(membershipRegistration);
        } catch (RuntimeException e) {
            // already shut down
        }
        background.shutdownNow();
        maintenance.shutdown();
        steps.shutdown();
        delivery.close();
    }
}
