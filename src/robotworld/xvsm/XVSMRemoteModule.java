package robotworld.xvsm;

import java.time.Duration;
import robotworld.space.Entry;
import robotworld.space.StringEntry;

/**
 * The module proxy on a computer without the module's hardware: each interface method writes a request to the
 * module's REQUEST container and waits, at most the call timeout, for its answer in the ANSWER container. It has
 * no thread of its own; calls run in the caller's thread, and any number of threads may call at once.
 *
 * <p>Failures are unchecked: {@link IllegalArgumentException} for an argument the interface refuses (checked here,
 * before anything is sent, as a local call would), {@link XVSMRemoteException} when the hardware failed at the
 * module's host, {@link ModuleCallTimeoutException} when no answer came in time or the hardware did not answer,
 * {@link ModuleCallException} when the space failed.
 *
 * <p>Subclasses map each interface method onto {@link #call}.
 */
public abstract class XVSMRemoteModule extends XVSMModule {

    private volatile Duration callTimeout;
    private volatile boolean closed;

    /** Looks up or creates the module's containers; the call timeout is the runtime's default. */
    protected XVSMRemoteModule(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
        this.callTimeout = runtime.defaultCallTimeout();
    }

    /** How long a call waits for its answer. */
    public Duration callTimeout() {
        return callTimeout;
    }

    /** Sets how long calls started from now on wait for their answer. */
    public void setCallTimeout(Duration timeout) {
        callTimeout = RuntimeDefaults.checkTimeout(timeout);
    }

    /**
     * Calls the module: sends {@code <host#call, args..., function>} and waits for the answer.
     *
     * @param function the function name (or code)
     * @param args     the arguments, converted with {@link Entry#from(Object)}
     * @return the answer (never an error answer: those are thrown)
     * @throws IllegalStateException when this proxy is closed
     */
    protected final CallTuple call(Object function, Object... args) {
        if (closed) {
            throw new IllegalStateException(this + " is closed");
        }
        CallTuple request = CallTuple.of(runtime().nextCallKey(), function, args);
        return new RemoteCall(this, request, functionName(request.function()), callTimeout.toMillis()).run();
    }

    /**
     * Sends a request without waiting for its answer, for the "quiet" functions that do not wait for the
     * hardware locally either. The request's key is this program's id {@code host#run} (the thesis's host name,
     * with the run that tells this program from another one on the same host), so its answer lands where this
     * program's previous answer of that kind was, displacing it: nothing piles up, and monitors still see it. A
     * hardware failure is not reported back, as in a local quiet call; nor is a refusal because the actuator was
     * stopped (the next call that waits for its answer is told).
     *
     * @throws ModuleCallException when the request cannot be written into the space
     */
    protected final void send(Object function, Object... args) {
        if (closed) {
            throw new IllegalStateException(this + " is closed");
        }
        CallTuple request = CallTuple.of(runtime().programId(), function, args);
        new RemoteCall(this, request, functionName(request.function()), callTimeout.toMillis()).send();
    }

    /** How a function field reads in messages; the default is the name itself. */
    protected String functionName(Entry function) {
        return function instanceof StringEntry name ? name.value() : function.toString();
    }

    /** Refuses further calls; calls in progress finish or time out. Idempotent. */
    @Override
    public void close() {
        closed = true;
    }
}
