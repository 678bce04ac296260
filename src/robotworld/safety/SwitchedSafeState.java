package robotworld.safety;

/**
 * The safety bookkeeping of a module that is switched on and off (the X10 lamp and appliance modules): its
 * configured {@link X10SafeState} and how it was last switched, for {@link Actuator#enterSafeState()} and
 * {@link Actuator#isEngaged()}. Thread-safe.
 */
public final class SwitchedSafeState {

    private final X10SafeState safeState;
    /** Whether it was last switched on; null before the first command. */
    private volatile Boolean switchedOn;

    public SwitchedSafeState(X10SafeState safeState) {
        this.safeState = java.util.Objects.requireNonNull(safeState, "safeState");
    }

    /** A command switches it on (also brighten and dim) or off; call before the command reaches the hardware. */
    public void commanded(boolean on) {
        switchedOn = on;
    }

    /** Puts it into its safe state with {@code on} or {@code off}; returns what was done. */
    public String enter(Runnable on, Runnable off) {
        String done = SafeStates.x10(safeState, on, off);
        if (safeState != X10SafeState.UNCHANGED) {
            switchedOn = safeState == X10SafeState.ON;
        }
        return done;
    }

    /** Whether it was last switched away from a safe state other than {@link X10SafeState#UNCHANGED}. */
    public boolean isEngaged() {
        Boolean on = switchedOn;
        return on != null && (safeState == X10SafeState.OFF && on || safeState == X10SafeState.ON && !on);
    }
}
