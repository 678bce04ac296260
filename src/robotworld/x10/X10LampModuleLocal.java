package robotworld.x10;

import robotworld.core.X10LampModule;

/**
 * Proxy for one X10 lamp module behind a CM11A, bound to its house and unit code. Brightness changes are given
 * in percent of the full range and sent as the nearest number of the 22 X10 dim steps.
 */
public class X10LampModuleLocal extends X10SwitchedModule implements X10LampModule {

    /** The module at {@code address}, driven through {@code controller}. */
    public X10LampModuleLocal(CM11aController controller, X10Address address) {
        super(controller, address, "lamp");
    }

    /** The module at house {@code house} (A..P), unit {@code unit} (1..16). */
    public X10LampModuleLocal(CM11aController controller, char house, int unit) {
        this(controller, X10Address.of(house, unit));
    }

    @Override
    public void brighten(int level) {
        controller.bright(address, DimSteps.ofPercent(level));
    }

    @Override
    public void dim(int level) {
        controller.dim(address, DimSteps.ofPercent(level));
    }
}
