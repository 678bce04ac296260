package robotworld.safety;

/**
 * A module that moves or switches something, as the safety layer sees it: it can be put into its safe state, and
 * it knows whether the commands it carried out may have left it away from that state. The space proxies of the
 * actuator modules ({@code XVSMMotorModuleLocal}, ...) implement it; a new module type that moves something
 * implements it in its Local proxy, and is then stopped like the others.
 *
 * <p>Safe states of the built-in module types (see the module pages in {@code docs/modules/}): motors 0; servos
 * hold their position (no new target is sent); X10 modules stay as they are, unless configured to be switched
 * off or on ({@link X10SafeState}).
 */
public interface Actuator {

    /**
     * Puts the hardware into its safe state. Must be safe to call at any time, from any thread, also while a
     * command is being carried out, and more than once.
     *
     * @return what it did, in words, e.g. {@code motors 1-8 set to 0} or {@code servos hold their positions}
     * @throws Exception when the hardware could not be reached; the actuator then stays engaged
     */
    String enterSafeState() throws Exception;

    /**
     * Whether the commands carried out since the last safe state may have left the actuator away from it (a motor
     * set to a speed other than 0, a lamp switched on that is to be off when stopped). Losing the commander of an
     * engaged actuator stops it; an actuator at rest is left alone.
     */
    boolean isEngaged();
}
