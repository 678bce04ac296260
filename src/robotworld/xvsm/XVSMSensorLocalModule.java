package robotworld.xvsm;

/**
 * The local proxy of a sensor module, with optional adaptive batching (thesis 6.3.1): since every waiting
 * requester wants the same, current sensor state, the serving thread can take all waiting requests at once,
 * read the hardware once, and answer them all. Off by default (the thesis's one-at-a-time processing); switch it
 * on with {@link #setAdaptiveBatching(boolean)}, the constructor flag, or {@code -Drwe.sensor.batching=true}.
 *
 * @param <H> the sensor module interface
 */
public abstract class XVSMSensorLocalModule<H> extends XVSMLocalModule<H> {

    /** With batching as {@code adaptiveBatching} says. */
    protected XVSMSensorLocalModule(XVSMRuntime runtime, String participant, String moduleName, H hardware,
                                    boolean adaptiveBatching) {
        super(runtime, participant, moduleName, hardware);
        useAdaptiveBatching(adaptiveBatching);
    }

    /**
     * Reads the hardware at most once per batch. Every answer must be derivable from the shared readings, so a
     * batched answer equals what the call would have returned on its own at that moment.
     */
    @Override
    protected abstract Performer batchPerformer();

    /** Whether waiting requests are answered from one hardware read. */
    public boolean isAdaptiveBatching() {
        return usesAdaptiveBatching();
    }

    /** Switches adaptive batching on or off; takes effect with the next batch. */
    public void setAdaptiveBatching(boolean on) {
        useAdaptiveBatching(on);
    }
}
