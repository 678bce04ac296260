package robotworld.x10;

/**
 * What every X10 module proxy shares: the controller it talks through, its address, and on/off. Lamp and
 * appliance proxies add their own functions on top.
 */
abstract class X10SwitchedModule {

    protected final CM11aController controller;
    protected final X10Address address;
    private final String kind;

    X10SwitchedModule(CM11aController controller, X10Address address, String kind) {
        if (controller == null || address == null) {
            throw new IllegalArgumentException("controller and address are required");
        }
        this.controller = controller;
        this.address = address;
        this.kind = kind;
    }

    /** The module's address. */
    public X10Address address() {
        return address;
    }

    /** Switches the module on. */
    public void on() {
        controller.on(address);
    }

    /** Switches the module off. */
    public void off() {
        controller.off(address);
    }

    @Override
    public String toString() {
        return "X10 " + kind + " " + address + " on " + controller.portName();
    }
}
