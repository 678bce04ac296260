package robotworld.bus;

import robotworld.core.GripperModule;

/** Test-only hardware proxy of {@link GripperModule}: holding register 0 is the force. */
public class GripperModuleProxy implements GripperModule {

    private final RS485Bus bus;
    private final int address;

    public GripperModuleProxy(RS485Bus bus, int address, String name) {
        this.bus = bus;
        this.address = address;
        bus.nameModule(address, name);
    }

    @Override
    public void grip(int force) {
        bus.writeRegister(address, 0, force);
    }

    @Override
    public int force() {
        return bus.readHoldingRegisters(address, 0, 1)[0];
    }
}
