package robotworld.sim;

import robotworld.x10.X10Address;
import robotworld.x10.X10Function;

/** State of one simulated X10 module on the power line. Thread-safe. */
public abstract class SimulatedX10Module {

    /** What kind of module it is. */
    public enum Kind { LAMP, APPLIANCE }

    private final X10Address address;
    private boolean on;

    protected SimulatedX10Module(X10Address address) {
        this.address = address;
    }

    /** The module's address. */
    public X10Address address() {
        return address;
    }

    /** Lamp or appliance. */
    public abstract Kind kind();

    /** Whether the module is switched on. */
    public synchronized boolean isOn() {
        return on;
    }

    protected synchronized void setOn(boolean value) {
        on = value;
    }

    /** Reacts to a function addressed to this module (or to its whole house). */
    abstract void apply(X10Function function, int dimSteps);

    /** Reacts to Preset Dim to {@code level} of 31; the default (an appliance) ignores it. */
    void applyPresetDim(int level) {
    }

    /** Reacts to an extended code sent to this module; the default ignores it. */
    void applyExtended(int data, int command) {
    }

    /** Whether the module counts as dimmed in the interface's status. */
    boolean isDimmed() {
        return false;
    }
}
