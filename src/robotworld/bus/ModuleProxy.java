package robotworld.bus;

import java.util.Objects;

/**
 * What every hardware proxy shares: the bus it talks through, its bus address ({@code <NodeNumber>} in a robot
 * description) and a name for messages. A proxy names itself on the bus, so any failure of one of its calls
 * reads e.g. "BumperModule 'Bumper-Sensor' at address 2 on /dev/ttyUSB0: no reply ...".
 */
public abstract class ModuleProxy {

    private final RS485Bus bus;
    private final int address;
    private final String name;

    /**
     * @param moduleClass the module interface's simple name, e.g. "BumperModule"
     * @param name the module's name in the description, or null
     */
    protected ModuleProxy(String moduleClass, RS485Bus bus, int address, String name) {
        this.bus = Objects.requireNonNull(bus, "bus");
        if (address < 1 || address > 247) {
            throw new IllegalArgumentException("bus address " + address + " is outside 1..247");
        }
        this.address = address;
        this.name = name;
        bus.nameModule(address, name == null ? moduleClass : moduleClass + " '" + name + "'");
    }

    /** The bus this module is on. */
    public RS485Bus bus() {
        return bus;
    }

    /** The module's bus address. */
    public int address() {
        return address;
    }

    /** The module's name from its description, or null. */
    public String name() {
        return name;
    }

    @Override
    public String toString() {
        return bus.describe(address) + " on " + bus.portName();
    }
}
