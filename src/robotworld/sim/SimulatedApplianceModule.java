package robotworld.sim;

import robotworld.x10.X10Address;
import robotworld.x10.X10Function;

/** A simulated appliance module (e.g. AM466): On and Off, All Units Off; lights-only and dim functions are ignored. */
public final class SimulatedApplianceModule extends SimulatedX10Module {

    public SimulatedApplianceModule(X10Address address) {
        super(address);
    }

    @Override
    public Kind kind() {
        return Kind.APPLIANCE;
    }

    @Override
    void apply(X10Function function, int dimSteps) {
        switch (function) {
            case ON -> setOn(true);
            case OFF, ALL_UNITS_OFF -> setOn(false);
            default -> {
                // appliance modules do not dim and are not lights
            }
        }
    }

    @Override
    public String toString() {
        return address() + " appliance " + (isOn() ? "on" : "off");
    }
}
