package robotworld.x10;

import robotworld.core.X10ApplianceModule;

/** Proxy for one X10 appliance module behind a CM11A, bound to its house and unit code. */
public class X10ApplianceModuleLocal extends X10SwitchedModule implements X10ApplianceModule {

    /** The module at {@code address}, driven through {@code controller}. */
    public X10ApplianceModuleLocal(CM11aController controller, X10Address address) {
        super(controller, address, "appliance");
    }

    /** The module at house {@code house} (A..P), unit {@code unit} (1..16). */
    public X10ApplianceModuleLocal(CM11aController controller, char house, int unit) {
        this(controller, X10Address.of(house, unit));
    }
}
