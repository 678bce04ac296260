package robotworld.safety;

import java.time.Duration;
import java.util.function.Consumer;
import robotworld.bus.ModuleProxy;
import robotworld.bus.MotorModuleProxy;
import robotworld.core.MotorModule;
import robotworld.core.ServoModule;
import robotworld.core.X10ApplianceModule;
import robotworld.core.X10LampModule;

/**
 * The safe states of the built-in module types, as actions on their hardware, for the actuators' proxies to
 * use. What each does is documented on the module's page in {@code docs/modules/}.
 */
public final class SafeStates {

    /** What stopping a servo module does: nothing is sent, every servo keeps its target. */
    public static final String SERVOS_HOLD = "servos hold their positions (no new target)";

    private SafeStates() {
    }

    /**
     * Sets every motor of a motor module to 0. On the bus this is one frame (write multiple registers 0x10 over
     * holding registers 0..7), so all motors stop at the same moment.
     *
     * @return {@code motors 1-8 set to 0}
     * @throws RuntimeException what the hardware throws
     */
    public static String stopMotors(MotorModule motors) {
        if (motors instanceof MotorModuleProxy proxy) {
            proxy.bus().writeRegisters(proxy.address(), 0, new int[MotorModule.MOTORS]);
        } else {
            for (int motor = 1; motor <= MotorModule.MOTORS; motor++) {
                motors.setMotor(motor, 0);
            }
        }
        return "motors 1-" + MotorModule.MOTORS + " set to 0";
    }

    /**
     * The actuator view of a hardware proxy, for programs without Local proxies ({@link HardwareSafety}): motor,
     * servo and X10 modules by their interface, anything implementing {@link Actuator} as itself; null for a
     * sensor. Such an actuator is never engaged (the rules that need commanders and a space do not apply).
     */
    public static Actuator actuatorOf(Object hardware, X10SafeState x10) {
        if (hardware instanceof Actuator actuator) {
            return actuator;
        }
        if (hardware instanceof MotorModule motors) {
            return atRest(() -> stopMotors(motors));
        }
        if (hardware instanceof ServoModule) {
            return atRest(() -> SERVOS_HOLD);
        }
        if (hardware instanceof X10LampModule lamp) {
            return atRest(() -> x10(x10, lamp::on, lamp::off));
        }
        if (hardware instanceof X10ApplianceModule appliance) {
            return atRest(() -> x10(x10, appliance::on, appliance::off));
        }
        return null;
    }

    private static Actuator atRest(java.util.function.Supplier<String> safeState) {
        return new Actuator() {
            @Override
            public String enterSafeState() {
                return safeState.get();
            }

            @Override
            public boolean isEngaged() {
                return false;
            }
        };
    }

    /**
     * Arms the communication watchdog of a module on the robot bus ({@code RS485Bus#armWatchdog}); does nothing for
     * hardware that is not a bus module proxy, or when {@code millis} is 0.
     *
     * @param onTrip told whenever the module is found to have tripped while this program feeds it
     * @return whether the watchdog is armed
     */
    public static boolean armWatchdog(Object hardware, int millis, Consumer<String> onTrip) {
        return armWatchdog(hardware, millis, onTrip, detail -> { });
    }

    /**
     * {@link #armWatchdog(Object, int, Consumer)}; {@code onFoundTripped} is told when the module had stopped by its
     * watchdog before this program armed it (its previous program died or went silent).
     */
    public static boolean armWatchdog(Object hardware, int millis, Consumer<String> onTrip,
                                      Consumer<String> onFoundTripped) {
        if (millis <= 0 || !(hardware instanceof ModuleProxy proxy)) {
            return false;
        }
        return proxy.bus().armWatchdog(proxy.address(), Duration.ofMillis(millis), onTrip, onFoundTripped);
    }

    /** Stops feeding the watchdog of a bus module proxy armed with {@link #armWatchdog}. */
    public static void releaseWatchdog(Object hardware) {
        if (hardware instanceof ModuleProxy proxy) {
            proxy.bus().watchdog().release(proxy.address());
        }
    }

    /**
     * Puts an X10 module into its configured safe state.
     *
     * @param on  switches it on
     * @param off switches it off
     * @return what was done
     */
    public static String x10(X10SafeState state, Runnable on, Runnable off) {
        switch (state) {
            case OFF -> {
                off.run();
                return "switched off";
            }
            case ON -> {
                on.run();
                return "switched on";
            }
            default -> {
                return "left as it is (X10 safe state: unchanged)";
            }
        }
    }
}
