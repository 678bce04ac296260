package robotworld.sim.robot;

import robotworld.bus.modbus.ExceptionCodes;

/**
 * A simulated bus module: an address, an identity and a Modbus data model (discrete inputs, input registers,
 * holding registers, all 0-based). Subclasses give the data meaning. Every method runs under the
 * {@link Simulation}'s lock.
 */
public abstract class SimModule {

    private final int address;
    private final ModuleIdentity identity;
    private final ModuleFaults faults;
    private final ModuleWatchdog watchdog = new ModuleWatchdog();

    protected SimModule(int address, ModuleIdentity identity, ModuleFaults faults) {
        if (address < 1 || address > 247) {
            throw new IllegalArgumentException("bus address " + address + " is outside 1..247");
        }
        this.address = address;
        this.identity = identity;
        this.faults = faults;
    }

    public int address() {
        return address;
    }

    public ModuleIdentity identity() {
        return identity;
    }

    public ModuleFaults faults() {
        return faults;
    }

    /** The module's communication watchdog (see {@link ModuleWatchdog}). */
    ModuleWatchdog watchdog() {
        return watchdog;
    }

    /** The watchdog timeout the master set, in ms; 0 when off. */
    public int watchdogMillis() {
        return watchdog.timeoutMillis();
    }

    /** Whether the watchdog tripped since the master last set its timeout. */
    public boolean watchdogTripped() {
        return watchdog.tripped();
    }

    /** How often the watchdog has tripped. */
    public long watchdogTrips() {
        return watchdog.trips();
    }

    /**
     * Goes to the module's safe state because its watchdog tripped: motors stop; servos hold (nothing changes);
     * sensors have none. The default does nothing.
     */
    void enterSafeState() {
    }

    /** The module class it simulates, e.g. "BumperModule". */
    public abstract String moduleClass();

    int discreteInputCount() {
        return 0;
    }

    boolean discreteInput(int index) {
        return false;
    }

    int inputRegisterCount() {
        return 0;
    }

    int inputRegister(int index) {
        return 0;
    }

    int holdingRegisterCount() {
        return 0;
    }

    int holdingRegister(int index) {
        return 0;
    }

    /**
     * Writes a holding register.
     *
     * @param value the unsigned 16-bit word received
     * @throws ModbusRefusal when the value is out of the module's range
     */
    void writeHoldingRegister(int index, int value) throws ModbusRefusal {
        throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_ADDRESS, "no holding registers");
    }

    /** Advances the module's own dynamics (ramps, servo travel) by {@code seconds}. */
    void step(double seconds) {
    }

    @Override
    public String toString() {
        return moduleClass() + " at address " + address + " (" + identity.nodeId() + ")";
    }
}
