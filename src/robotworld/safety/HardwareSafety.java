package robotworld.safety;

import java.util.concurrent.ThreadLocalRandom;
import robotworld.core.HostNames;
import robotworld.core.MotorModule;

/**
 * The clean-exit rule and the bus watchdogs for a program that drives its own hardware without a space (generated
 * projects of communication type {@code none}): it knows the safe state of every actuator it was given
 * ({@link #guard}), arms the bus watchdog of motor modules, and puts them all into their safe state when the program
 * ends: {@link #close()}, {@link #failed}, or a JVM shutdown (Ctrl-C, SIGTERM, {@code System.exit}).
 *
 * <pre>{@code
 * HardwareSafety safety = HardwareSafety.forProgram("MyRobot");
 * MotorModule motor = safety.guard("MyRobot", "Motor", new MotorModuleProxy(bus, 1, "Motor"));
 * ...
 * safety.close();   // motors 0, before the bus is closed
 * }</pre>
 */
public final class HardwareSafety implements AutoCloseable {

    private final SafetySupervisor supervisor;
    private final Thread hook;
    private volatile boolean closed;

    private HardwareSafety(String program) {
        String host = HostNames.thisComputer();
        String id = host + "#" + Long.toString(ThreadLocalRandom.current().nextLong() >>> 28, 36);
        this.supervisor = new SafetySupervisor(null, id, host, SafetySettings.fromSystem());
        this.hook = new Thread(() -> close(StopCause.SHUTDOWN,
                "the JVM is shutting down (Ctrl-C, SIGTERM or System.exit)"), "safety-shutdown " + program);
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** The safety of a program named {@code program}; a JVM shutdown stops its actuators. */
    public static HardwareSafety forProgram(String program) {
        return new HardwareSafety(program);
    }

    /** The description's safety values of a module; before {@link #guard} for it. */
    public void describe(String participant, String module, ModuleSafety safety) {
        supervisor.describe(participant, module, safety);
    }

    /**
     * Puts {@code hardware} under this program's safety if it is an actuator (a motor, servo or X10 module, or
     * anything implementing {@link Actuator}), and arms the bus watchdog of a motor module; a sensor is returned
     * untouched.
     *
     * @return {@code hardware}
     */
    public <T> T guard(String participant, String module, T hardware) {
        Actuator actuator = SafeStates.actuatorOf(hardware, supervisor.x10SafeState(participant, module));
        if (actuator != null) {
            supervisor.guard(participant, module, actuator);
            int typeDefault = hardware instanceof MotorModule ? SafetySettings.DEFAULT_MOTOR_WATCHDOG_MILLIS : 0;
            SafeStates.armWatchdog(hardware, supervisor.watchdogMillis(participant, module, typeDefault),
                    detail -> supervisor.watchdogTripped(participant, module, detail),
                    detail -> supervisor.watchdogFoundTripped(participant, module, detail));
        }
        return hardware;
    }

    /** The program failed: every actuator into its safe state now. */
    public void failed(Throwable failure) {
        supervisor.stopAll(StopCause.PROGRAM_FAILED, "the program failed: " + failure);
    }

    /** The program ends: every actuator into its safe state (unless {@link #failed} did so already). */
    @Override
    public void close() {
        close(StopCause.PROGRAM_ENDED, "the program ended");
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the hook runs or has run
        }
    }

    private void close(StopCause cause, String reason) {
        if (closed) {
            return;
        }
        closed = true;
        supervisor.close(cause, reason);
    }

    /** The stops of this program, newest last. */
    public java.util.List<StopRecord> recentStops() {
        return supervisor.recentStops();
    }
}
