package robotworld.xvsm;

import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.core.HostNames;
import robotworld.core.RuntimeSettings;
import robotworld.safety.SafetySettings;
import robotworld.safety.SafetySupervisor;
import robotworld.safety.StopCause;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.remote.SpaceUrls;

/**
 * One participant program's connection to the space and everything it runs on it: its host name, the resources
 * it owns (buses, CM11A controllers, module proxies), one background thread that publishes local calls and
 * tidies up after timed-out calls, and the defaults of its module proxies. Generated frameworks do:
 *
 * <pre>{@code
 * try (XVSMRuntime runtime = XVSMRuntime.connect(SPACE_URL, HOST)) {
 *     RS485Bus bus = runtime.own(new RS485Bus(runtime.port(NAME, "bus", "/dev/ttyUSB0")));
 *     MotorModule motor = runtime.own(new XVSMMotorModuleLocal(runtime, NAME, "Motor-Controller",
 *             new MotorModuleProxy(bus, 1, "Motor-Controller")));
 *     ...
 *     runtime.serveUntilStopped();
 * }
 * }</pre>
 *
 * <p><b>Run-time overrides</b> ({@link RuntimeSettings}): space URL {@code rwe.space.url}, token
 * {@code rwe.space.token}, host name {@code rwe.host}, ports {@code rwe.port.<Participant>.<kind>}; and for the
 * proxies: call timeout {@code rwe.call.timeout.ms} (default 10 000), local-call publishing
 * {@code rwe.publish.local} (default true), adaptive sensor batching {@code rwe.sensor.batching} (default false);
 * each also as an environment variable ({@code RWE_CALL_TIMEOUT_MS}, ...).
 *
 * <p><b>Safety</b> ({@link #safety()}, package {@code robotworld.safety}): the actuators this program serves are put
 * into their safe state when it ends ({@link #close()}, {@link #failed}, a JVM shutdown), when a remote commander of
 * theirs goes silent, when the space through which a remote commander drove them is lost, and on a stop request;
 * the program sends a heartbeat into the space.
 *
 * <p>Thread-safe.
 */
public final class XVSMRuntime implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(XVSMRuntime.class);
    private static final long PUBLISH_GRACE_MILLIS = 1_000;

    private final Capi space;
    /** The space as the module proxies use it: every answer counts as contact for the safety layer. */
    private final Capi moduleSpace;
    private final boolean ownsSpace;
    private final String hostName;
    private final RuntimeSettings settings;
    private final ScheduledExecutorService background;
    private final LocalPublisher publisher;
    private final AbandonedCalls abandoned;
    private final String callKeyPrefix;
    private final String programId;
    private final SafetySupervisor safety;
    private final AtomicLong calls = new AtomicLong();
    private final Deque<AutoCloseable> owned = new ArrayDeque<>();
    private final CountDownLatch closedLatch = new CountDownLatch(1);
    private volatile Duration defaultCallTimeout;
    private volatile boolean publishLocalCallsByDefault;
    private volatile boolean adaptiveBatchingByDefault;
    private boolean closing;
    private Thread shutdownHook;

    private XVSMRuntime(Capi space, boolean ownsSpace, String hostName, RuntimeSettings settings,
                        RuntimeDefaults defaults) {
        this.space = Objects.requireNonNull(space, "space");
        this.ownsSpace = ownsSpace;
        this.hostName = checkHostName(hostName);
        this.settings = settings;
        this.defaultCallTimeout = defaults.callTimeout();
        this.publishLocalCallsByDefault = defaults.publishLocalCalls();
        this.adaptiveBatchingByDefault = defaults.sensorBatching();
        ScheduledThreadPoolExecutor executor = new ScheduledThreadPoolExecutor(1, task -> {
            Thread thread = new Thread(task, "xvsm-background " + hostName);
            thread.setDaemon(true);
            return thread;
        });
        executor.setExecuteExistingDelayedTasksAfterShutdownPolicy(false);
        this.background = executor;
        this.publisher = new LocalPublisher(background);
        this.abandoned = new AbandonedCalls(background);
        // the tag tells this run's calls from those of an earlier run with the same host name
        this.programId = hostName + "#" + Long.toString(ThreadLocalRandom.current().nextLong() >>> 28, 36);
        this.callKeyPrefix = programId + ".";
        this.safety = new SafetySupervisor(space, programId, hostName, SafetySettings.fromSystem());
        // every answer of the space proves it reachable: a busy program is never taken for a cut-off one
        this.moduleSpace = safety.tracking(space);
    }

    /**
     * Connects to the space: the URL and host name from the run-time overrides ({@link RuntimeSettings#fromSystem()}),
     * else the given defaults from the description. A {@code null} host means this computer's host name; a
     * {@code null} URL is only allowed when it is overridden. The URL may list the servers of a clustered space,
     * separated by commas ({@link SpaceUrls}); they are opened with {@link RemoteSpace}, which fails over from one
     * to the next (with the token of {@code rwe.space.token}, if any).
     *
     * @throws IllegalStateException    when no space URL is set anywhere
     * @throws IllegalArgumentException for a URL that is not http(s), or a host name with a '#'
     * @throws robotworld.space.SpaceException when the space cannot be reached
     */
    public static XVSMRuntime connect(String spaceUrlFromDescription, String hostFromDescription) {
        RuntimeSettings settings = RuntimeSettings.fromSystem();
        String url = settings.spaceUrl(spaceUrlFromDescription);
        String host = settings.hostName(isBlank(hostFromDescription) ? localHostName() : hostFromDescription);
        Capi space = openSpace(url, settings.spaceToken());
        try {
            return new XVSMRuntime(space, true, host, settings, RuntimeDefaults.fromSystem());
        } catch (RuntimeException e) {
            space.close();
            throw e;
        }
    }

    /** For tests and embedding: runs on an existing space, which closing the runtime leaves open. */
    public static XVSMRuntime using(Capi space, String hostName) {
        return using(space, hostName, false);
    }

    /** Runs on an existing space; {@code closeSpace} says whether closing the runtime closes it too. */
    public static XVSMRuntime using(Capi space, String hostName, boolean closeSpace) {
        return new XVSMRuntime(space, closeSpace, hostName, RuntimeSettings.fromSystem(), RuntimeDefaults.fromSystem());
    }

    /** The space this runtime works on. */
    public Capi space() {
        return space;
    }

    /** The space for the module proxies: {@link #space()}, telling the safety layer of every answer. */
    Capi moduleSpace() {
        return moduleSpace;
    }

    /** This computer's name in the space: the key of its requests and of its published local calls. */
    public String hostName() {
        return hostName;
    }

    /**
     * A participant's serial port: the override ({@code rwe.port.<participant>.<kind>} or
     * {@code RWE_PORT_<PARTICIPANT>_<KIND>}) or {@code fromDescription}.
     *
     * @param kind {@code bus} or {@code x10}
     * @throws IllegalStateException when neither is set
     */
    public String port(String participant, String kind, String fromDescription) {
        return settings.port(participant, kind, fromDescription);
    }

    /**
     * Registers a resource to close when the runtime closes; resources close in reverse order of registration
     * (a module proxy before the bus it uses). Registering the same object twice has no further effect.
     *
     * @return {@code resource}
     * @throws IllegalStateException when the runtime is closed (the resource is closed first)
     */
    public <T extends AutoCloseable> T own(T resource) {
        Objects.requireNonNull(resource, "resource");
        synchronized (this) {
            if (!closing) {
                if (owned.stream().noneMatch(r -> r == resource)) {
                    owned.push(resource);
                }
                return resource;
            }
        }
        closeQuietly(resource);
        throw new IllegalStateException("the runtime of host " + hostName + " is closed");
    }

    /**
     * Blocks until {@link #close()} is called or the JVM shuts down; a shutdown hook closes the runtime, so a
     * provider stopped with Ctrl-C releases its hardware and stops its module threads.
     */
    public void serveUntilStopped() throws InterruptedException {
        long serving;
        synchronized (this) {
            closeOnShutdown();
            serving = owned.stream().filter(XVSMLocalModule.class::isInstance).count();
        }
        // a provider is otherwise silent: say once what it does and how to stop it
        LOG.info("{} serving {} module(s) through {}; stop with Ctrl-C", hostName, serving, space.spaceUri());
        closedLatch.await();
    }

    /**
     * Puts every actuator this program serves into its safe state at once, because the program failed; every later
     * command of an actuator is refused. For a {@code catch} around the control program: the runtime's close (in a
     * {@code finally} or try-with-resources) then finds them stopped. Generated main classes do this.
     *
     * @param failure what the program failed with, for the log and the stop records
     */
    public void failed(Throwable failure) {
        safety.stopAll(StopCause.PROGRAM_FAILED, "the program failed: " + failure);
    }

    /**
     * Closes the runtime: first puts every actuator this program serves into its safe state (motors 0, servos
     * hold, X10 modules as configured) and refuses later commands, then closes owned resources in reverse order
     * (module proxies stop their threads), publishes what local calls left queued (for at most a second), tidies
     * up after abandoned calls, sends a last heartbeat saying the program ended, and closes the space if this
     * runtime opened it. Idempotent; failures while closing are logged, not thrown.
     */
    @Override
    public void close() {
        close(StopCause.PROGRAM_ENDED, "the program ended");
    }

    private void close(StopCause cause, String reason) {
        List<AutoCloseable> resources;
        synchronized (this) {
            if (closing) {
                return;
            }
            closing = true;
            resources = new ArrayList<>(owned);
            owned.clear();
        }
        // actuators first: the hardware below them is closed next
        safety.stopAll(cause, reason);
        resources.forEach(XVSMRuntime::closeQuietly);
        try {
            publisher.awaitPublished(PUBLISH_GRACE_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        background.shutdownNow();
        abandoned.sweepNow();
        safety.close(cause, reason);
        if (ownsSpace) {
            closeQuietly(space);
        }
        closedLatch.countDown();
        removeShutdownHook();
    }

    /** Whether {@link #close()} has been called. */
    public synchronized boolean isClosed() {
        return closing;
    }

    // ----- defaults for the module proxies created afterwards -----

    /** The call timeout new remote proxies start with ({@code rwe.call.timeout.ms}, default 10 s). */
    public Duration defaultCallTimeout() {
        return defaultCallTimeout;
    }

    /** Sets the call timeout for remote proxies created from now on. */
    public void setDefaultCallTimeout(Duration timeout) {
        defaultCallTimeout = RuntimeDefaults.checkTimeout(timeout);
    }

    /** Whether new local proxies publish local calls ({@code rwe.publish.local}, default true). */
    public boolean publishLocalCallsByDefault() {
        return publishLocalCallsByDefault;
    }

    /** Sets whether local proxies created from now on publish local calls. */
    public void setPublishLocalCallsByDefault(boolean publish) {
        publishLocalCallsByDefault = publish;
    }

    /** Whether new sensor proxies batch waiting requests ({@code rwe.sensor.batching}, default false). */
    public boolean adaptiveBatchingByDefault() {
        return adaptiveBatchingByDefault;
    }

    /** Sets whether sensor proxies created from now on batch waiting requests. */
    public void setAdaptiveBatchingByDefault(boolean batching) {
        adaptiveBatchingByDefault = batching;
    }

    // ----- for the module proxies -----

    /**
     * The safety layer of this program: the guards of the actuators it serves, its heartbeat, the rules that stop
     * actuators (see {@code robotworld.safety}), and its safety settings.
     */
    public SafetySupervisor safety() {
        return safety;
    }

    /**
     * This program's id in the space, {@code host#run}: the prefix of its call keys, the key of its heartbeat, and
     * how the programs serving actuators name their commanders.
     */
    public String programId() {
        return programId;
    }

    /** Registers a module proxy, so closing the runtime stops it even if nobody owns it explicitly. */
    void register(XVSMModule module) {
        own(module);
        if (module instanceof robotworld.safety.Actuator) {
            synchronized (this) {
                closeOnShutdown();
            }
        }
    }

    /**
     * A JVM shutdown (Ctrl-C, SIGTERM, {@code System.exit}) closes the runtime, which first stops the actuators.
     * Installed when the first actuator is served, or by {@link #serveUntilStopped()}. Called with the lock held.
     */
    private void closeOnShutdown() {
        if (!closing && shutdownHook == null) {
            shutdownHook = new Thread(() -> close(StopCause.SHUTDOWN,
                    "the JVM is shutting down (Ctrl-C, SIGTERM or System.exit)"), "xvsm-runtime-shutdown " + hostName);
            Runtime.getRuntime().addShutdownHook(shutdownHook);
        }
    }

    /** A key no other call of any host uses: {@code host#run.n}. */
    String nextCallKey() {
        return callKeyPrefix + calls.incrementAndGet();
    }

    LocalPublisher publisher() {
        return publisher;
    }

    AbandonedCalls abandonedCalls() {
        return abandoned;
    }

    /** Waits until the local calls made so far are published; for tests. */
    boolean awaitPublished(Duration timeout) throws InterruptedException {
        return publisher.awaitPublished(timeout.toMillis());
    }

    @Override
    public String toString() {
        return "XVSMRuntime[" + hostName + " on " + space.spaceUri() + "]";
    }

    // ----- helpers -----

    private static Capi openSpace(String url, String token) {
        // one server's URL, or the servers of a cluster separated by commas: calls fail over between them
        return RemoteSpace.open(SpaceUrls.parse(url), RemoteSpace.Options.defaults().token(token));
    }

    private static String checkHostName(String hostName) {
        if (isBlank(hostName)) {
            throw new IllegalArgumentException("a host name must not be blank");
        }
        if (hostName.indexOf('#') >= 0) {
            throw new IllegalArgumentException("a host name must not contain '#' (it separates host and call in "
                    + "answer keys): " + hostName);
        }
        return hostName;
    }

    private static String localHostName() {
        return HostNames.thisComputer();
    }

    private static boolean isBlank(String text) {
        return text == null || text.isBlank();
    }

    private static void closeQuietly(AutoCloseable resource) {
        try {
            resource.close();
        } catch (Exception e) {
            LOG.warn("closing {} failed: {}", resource, e.toString());
        }
    }

    private void removeShutdownHook() {
        Thread hook;
        synchronized (this) {
            hook = shutdownHook;
        }
        if (hook != null && hook != Thread.currentThread()) {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // the JVM is exiting; the hook runs or has run
            }
        }
    }
}
