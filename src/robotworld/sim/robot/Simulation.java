package robotworld.sim.robot;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Function;

/**
 * The simulated robot's state: its world and its bus modules, advanced in time by a ticker thread (scaled by a
 * time factor) or by hand in tests. One lock guards everything, so a bus request sees a consistent world.
 */
public final class Simulation implements AutoCloseable {

    /** Longest simulated step: longer pauses are cut into these, so the robot cannot tunnel through walls. */
    private static final double MAX_STEP_SECONDS = 0.005;
    private static final long TICK_NANOS = 5_000_000L;
    /** A tick this late means the simulator's thread did not get the CPU (a busy machine), not that time passed. */
    private static final long STALL_NANOS = 50_000_000L;

    private final World world;
    private final Map<Integer, SimModule> modules = new TreeMap<>();
    private final SimMotorModule drive;
    private final double timeScale;
    private volatile Thread ticker;
    private double simulatedSeconds;

    /**
     * @param timeScale simulated seconds per real second when the ticker runs (1 = real time)
     * @throws IllegalArgumentException when two modules share an address
     */
    public Simulation(World world, List<SimModule> moduleList, double timeScale) {
        if (!(timeScale > 0)) {
            throw new IllegalArgumentException("time scale must be positive, was " + timeScale);
        }
        this.world = world;
        this.timeScale = timeScale;
        SimMotorModule wheels = null;
        for (SimModule module : moduleList) {
            if (modules.putIfAbsent(module.address(), module) != null) {
                throw new IllegalArgumentException("two modules at bus address " + module.address());
            }
            if (wheels == null && module instanceof SimMotorModule motor && motor.drivesWheels()) {
                wheels = motor;
            }
        }
        this.drive = wheels;
    }

    /** Advances modules and world by {@code seconds} of simulated time. */
    public synchronized void step(double seconds) {
        double left = seconds;
        while (left > 1e-12) {
            double dt = Math.min(left, MAX_STEP_SECONDS);
            for (SimModule module : modules.values()) {
                module.step(dt);
            }
            if (drive != null) {
                world.drive(drive.leftWheel(), drive.rightWheel(), dt);
            }
            simulatedSeconds += dt;
            left -= dt;
        }
    }

    /** Starts advancing time in the background, {@code timeScale} simulated seconds per real second. */
    public synchronized void start() {
        if (ticker != null) {
            return;
        }
        Thread thread = new Thread(this::tick, "robot-sim-ticker");
        thread.setDaemon(true);
        ticker = thread;
        thread.start();
    }

    private void tick() {
        long last = System.nanoTime();
        while (ticker == Thread.currentThread()) {
            java.util.concurrent.locks.LockSupport.parkNanos(TICK_NANOS);
            long now = System.nanoTime();
            step((now - last) / 1e9 * timeScale);
            if (now - last > STALL_NANOS) {
                // this JVM did not run the simulator for a while: a module's own clock would not have stopped, but
                // neither would the master's frames have stopped reaching it, so the pause does not count as silence
                stalled(now - last - TICK_NANOS);
            }
            checkWatchdogs(now);
            last = now;
        }
    }

    /** Stops the ticker and waits (up to a second) until it has made its last step, so time stands still after. */
    @Override
    public void close() {
        Thread running = ticker;
        ticker = null;
        if (running != null && running != Thread.currentThread()) {
            try {
                running.join(1_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Reads the world consistently, e.g. {@code simulation.inspect(World::pose)}. */
    public synchronized <T> T inspect(Function<World, T> reader) {
        return reader.apply(world);
    }

    /** Simulated time since the start, in seconds. */
    public synchronized double simulatedSeconds() {
        return simulatedSeconds;
    }

    /** The module at {@code address}, or null. */
    public SimModule module(int address) {
        return modules.get(address);
    }

    /** All modules by address. */
    public Map<Integer, SimModule> modules() {
        return Collections.unmodifiableMap(modules);
    }

    /** Answers a request PDU for {@code module} under the lock; the request feeds the module's watchdog. */
    synchronized byte[] respond(SimModule module, byte[] request) {
        module.watchdog().fed(System.nanoTime());
        byte[] watchdogAnswer = module.faults().refusal() == 0 ? module.watchdog().respond(request) : null;
        return watchdogAnswer != null ? watchdogAnswer : RequestHandler.respond(module, request);
    }

    private synchronized void stalled(long nanos) {
        for (SimModule module : modules.values()) {
            module.watchdog().stalled(nanos);
        }
    }

    /**
     * Trips the watchdogs whose timeout has run out, at real time {@code nanos}: the ticker calls it; tests that
     * step by hand may too.
     */
    public synchronized void checkWatchdogs(long nanos) {
        for (SimModule module : modules.values()) {
            if (module.watchdog().expired(nanos)) {
                module.enterSafeState(); // first: the tripped bit must never be read before the module is stopped
                module.watchdog().trip();
            }
        }
    }

    /** Applies a broadcast request to every module (no answers). */
    synchronized void broadcast(byte[] request) {
        for (SimModule module : modules.values()) {
            RequestHandler.applyBroadcast(module, request);
        }
    }
}
