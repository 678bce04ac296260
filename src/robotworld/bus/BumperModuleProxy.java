package robotworld.bus;

import robotworld.core.BumperModule;
import robotworld.core.ModuleArguments;

/** A bumper module on the bus. Register map: discrete input {@code n-1} = contact of bumper {@code n}. */
public class BumperModuleProxy extends ModuleProxy implements BumperModule {

    public BumperModuleProxy(RS485Bus bus, int address) {
        this(bus, address, null);
    }

    public BumperModuleProxy(RS485Bus bus, int address, String name) {
        super("BumperModule", bus, address, name);
    }

    @Override
    public int getAllBumper() {
        boolean[] contacts = bus().readDiscreteInputs(address(), 0, BUMPERS);
        int mask = 0;
        for (int i = 0; i < contacts.length; i++) {
            if (contacts[i]) {
                mask |= 1 << i;
            }
        }
        return mask;
    }

    @Override
    public boolean getSingleBumper(int bumperNumber) {
        ModuleArguments.bumperNumber(bumperNumber);
        return bus().readDiscreteInputs(address(), bumperNumber - 1, 1)[0];
    }
}
