package robotworld.xvsm;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.safety.Actuator;
import robotworld.safety.ActuatorGuard;
import robotworld.safety.SafeStates;
import robotworld.safety.StopCause;
import robotworld.space.Entry;

/**
 * The module proxy on the computer that has the hardware. It serves the module's REQUEST container without a
 * thread of its own (a take waiting in the space; then, on the program's serving pool, perform on the hardware and
 * shift the answer under the requester's key; see {@link RequestServer}), and lets the
 * control program on this computer call the hardware directly; each such local call is published into the ANSWER
 * container under this computer's host name, so monitors see it (switch off with
 * {@link #setPublishLocalCalls(boolean)} to save the space traffic).
 *
 * <p>A failed hardware call is answered with an error answer, and the thread goes on serving. Sensor modules may
 * batch: take every waiting request, read the hardware once, answer all ({@link #batchPerformer()}).
 *
 * <p><b>Actuators</b> (subclasses that implement {@link Actuator}) are guarded by the program's safety layer
 * ({@code robotworld.safety}): every command, local or remote, is first admitted by the actuator's
 * {@link ActuatorGuard}, which refuses it (without carrying it out) when the actuator was stopped since its
 * commander last commanded it; the caller gets an {@link ActuatorStoppedException}. Closing the proxy, or the
 * runtime, puts the actuator into its safe state.
 *
 * <p>Subclasses map their interface onto tuples: each interface method calls {@link #callLocally}, and
 * {@link #perform} carries out a request, for local and remote callers alike. A subclass constructor ends with
 * {@link #start()}.
 *
 * @param <H> the module interface, implemented by the hardware proxy
 */
public abstract class XVSMLocalModule<H> extends XVSMModule {

    private static final Logger LOG = LoggerFactory.getLogger(XVSMLocalModule.class);

    /** Carries out one request and returns the answer's values (the fields between key and function). */
    @FunctionalInterface
    protected interface Performer {
        /**
         * @throws MalformedCallException for an unknown function or wrong fields; any other exception is a
         *                                hardware failure
         */
        List<Entry> perform(CallTuple request);
    }

    private final H hardware;
    /** Set by {@link #start()}, when the subclass is ready: null for a sensor. */
    private volatile ActuatorGuard guard;
    private final RequestServer server;
    private volatile boolean publishLocalCalls;
    private volatile boolean adaptiveBatching;
    private volatile boolean closed;

    /**
     * Looks up or creates the module's containers; {@link #start()} then starts serving.
     *
     * @param hardware the hardware proxy (not closed by this class)
     */
    protected XVSMLocalModule(XVSMRuntime runtime, String participant, String moduleName, H hardware) {
        super(runtime, participant, moduleName);
        this.hardware = Objects.requireNonNull(hardware, "hardware");
        this.publishLocalCalls = runtime.publishLocalCallsByDefault();
        this.server = new RequestServer(containers, participant + "/" + moduleName, this::answerAll,
                () -> adaptiveBatching);
    }

    /**
     * The bus watchdog an actuator of this type gets when neither the description nor a setting gives one, in ms
     * (0 = none).
     */
    protected int defaultWatchdogMillis() {
        return 0;
    }

    /**
     * Starts serving requests; the last statement of a subclass's constructor. An actuator is guarded from here on,
     * and its bus watchdog armed.
     */
    protected final void start() {
        XVSMRuntime runtime = runtime();
        if (this instanceof Actuator actuator) {
            guard = runtime.safety().guard(participant(), moduleName(), actuator);
            int watchdog = runtime.safety().watchdogMillis(participant(), moduleName(), defaultWatchdogMillis());
            SafeStates.armWatchdog(hardware, watchdog,
                    detail -> runtime.safety().watchdogTripped(participant(), moduleName(), detail),
                    detail -> runtime.safety().watchdogFoundTripped(participant(), moduleName(), detail));
        } else {
            runtime.safety().serves(participant(), moduleName());
        }
        server.start();
    }

    /** The hardware proxy. */
    protected final H hardware() {
        return hardware;
    }

    /**
     * Carries out one request (from a remote caller, or a local call) on the hardware.
     *
     * @return the answer's values
     */
    protected abstract List<Entry> perform(CallTuple request);

    /**
     * The performer for one batch of requests. The default performs each request on its own; sensor modules
     * return one that reads the hardware at most once per kind of reading ({@link #readOnce}).
     */
    protected Performer batchPerformer() {
        return this::perform;
    }

    /**
     * A call of the control program on this computer: performed on the hardware in the caller's thread, then
     * (unless switched off) published under this host's name; a failure is published as an error answer and
     * thrown unchanged, as the hardware threw it.
     *
     * @param function the function name (or code)
     * @param args     the arguments, converted with {@link Entry#from(Object)}
     * @return the answer, for the subclass to read its value from
     */
    protected final CallTuple callLocally(Object function, Object... args) {
        CallTuple request = CallTuple.of(hostName(), function, args);
        String commander = runtime().programId();
        ActuatorGuard guard = this.guard;
        ActuatorGuard.Admission admission = guard == null ? null : guard.admit(commander, true);
        if (admission != null && !admission.admitted()) {
            ActuatorStoppedException refused = new ActuatorStoppedException(participant(), moduleName(),
                    request.functionText(), hostName(), admission.refusal().summary(), admission.advice());
            publish(ErrorAnswer.of(request, refused, hostName()).toAnswer(hostName()));
            throw refused;
        }
        CallTuple answer;
        try {
            answer = request.withFields(perform(request));
        } catch (RuntimeException e) {
            publish(ErrorAnswer.of(request, e, hostName()).toAnswer(hostName()));
            throw e;
        } finally {
            if (admission != null) {
                guard.performed(commander, admission);
            }
        }
        publish(answer);
        return answer;
    }

    /** The actuator's guard, or null for a sensor. */
    protected final ActuatorGuard guard() {
        return guard;
    }

    /** Whether local calls are published into the ANSWER container. */
    public boolean isPublishLocalCalls() {
        return publishLocalCalls;
    }

    /** Switches publishing of local calls on or off; off saves space traffic, but monitors only see remote calls. */
    public void setPublishLocalCalls(boolean publish) {
        publishLocalCalls = publish;
    }

    /** Whether the serving thread takes all waiting requests at once and answers them with {@link #batchPerformer()}. */
    protected final boolean usesAdaptiveBatching() {
        return adaptiveBatching;
    }

    /** Switches adaptive batching on or off (sensor modules offer it; see {@link XVSMSensorLocalModule}). */
    protected final void useAdaptiveBatching(boolean on) {
        adaptiveBatching = on;
    }

    /** Whether the serving thread runs. */
    public boolean isServing() {
        return server.isRunning();
    }

    /**
     * Stops the serving thread after it has answered what it has taken, and puts an actuator into its safe state
     * (unless the runtime's close already did); idempotent. The hardware stays open.
     */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        if (server != null) { // null when the constructor failed after registering with the runtime
            server.stop();
        }
        ActuatorGuard guard = this.guard;
        if (guard != null) {
            if (!guard.hasEnded()) {
                guard.stop(StopCause.PROGRAM_ENDED, "its proxy was closed", null, null);
            }
            runtime().safety().release(guard);
            SafeStates.releaseWatchdog(hardware);
        }
    }

    /**
     * A reading that happens at most once, however often it is asked for; a failure is remembered and thrown to
     * every asker. For {@link #batchPerformer()}.
     */
    protected static <T> Supplier<T> readOnce(Supplier<T> reading) {
        return new Supplier<>() {
            private T value;
            private RuntimeException failure;
            private boolean done;

            @Override
            public T get() {
                if (!done) {
                    done = true;
                    try {
                        value = reading.get();
                    } catch (RuntimeException e) {
                        failure = e;
                    }
                }
                if (failure != null) {
                    throw failure;
                }
                return value;
            }
        };
    }

    private void publish(CallTuple answer) {
        if (publishLocalCalls) {
            runtime().publisher().publish(containers, answer);
        }
    }

    /** The answers to one batch taken by the serving thread; failures become error answers. */
    private List<CallTuple> answerAll(List<CallTuple> requests) {
        Performer performer = adaptiveBatching ? batchPerformer() : this::perform;
        List<CallTuple> answers = new ArrayList<>(requests.size());
        for (CallTuple request : requests) {
            answers.add(answer(performer, request));
        }
        return answers;
    }

    private CallTuple answer(Performer performer, CallTuple request) {
        String commander = commanderOf(request.key());
        ActuatorGuard guard = this.guard;
        ActuatorGuard.Admission admission = guard == null ? null : guard.admit(commander, isWaitingCall(request.key()));
        if (admission != null && !admission.admitted()) {
            return ErrorAnswer.stopped(request, admission.refusal().summary(), hostName()).toAnswer(request.key());
        }
        try {
            return request.withFields(performer.perform(request));
        } catch (VirtualMachineError fatal) {
            throw fatal;
        } catch (Throwable failure) { // the thread must survive any failure of the hardware or its proxy
            LOG.debug("{}/{} {} failed: {}", participant(), moduleName(), request.functionText(), failure.toString());
            return ErrorAnswer.of(request, failure, hostName()).toAnswer(request.key());
        } finally {
            if (admission != null) {
                guard.performed(commander, admission);
            }
        }
    }

    /**
     * The program that sent a request: {@code host#run} of the key {@code host#run.n} (a call that waits for its
     * answer) or {@code host#run} (a quiet call); a key without {@code #} is taken as it is.
     */
    static String commanderOf(String key) {
        int hash = key.indexOf('#');
        if (hash < 0) {
            return key;
        }
        int dot = key.indexOf('.', hash);
        return dot < 0 ? key : key.substring(0, dot);
    }

    /** Whether the caller of a request waits for its answer (its key has a call number, {@code host#run.n}). */
    static boolean isWaitingCall(String key) {
        int hash = key.indexOf('#');
        return hash >= 0 && key.indexOf('.', hash) >= 0;
    }
}
