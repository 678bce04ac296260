package robotworld.sim.robot;

import java.util.ArrayList;
import java.util.List;

/**
 * Everything a simulated robot is made of: its bus (baud rate, line timing), its world (arena, obstacles, time
 * scale), its body and its modules. Read from a file by {@link SimRobotConfigReader}.
 *
 * @param seed seeds random fault injection, so a run can be repeated
 */
public record SimRobotConfig(String name, int baud, LineTiming timing, double timeScale, long seed,
        double arenaWidth, double arenaHeight, List<Rect> obstacles, Pose start, double radius, double wheelBase,
        double maxSpeed, List<ModuleSpec> modules) {

    public SimRobotConfig {
        obstacles = List.copyOf(obstacles);
        modules = List.copyOf(modules);
    }

    /** The same robot with another line timing. */
    public SimRobotConfig withTiming(LineTiming newTiming) {
        return new SimRobotConfig(name, baud, newTiming, timeScale, seed, arenaWidth, arenaHeight, obstacles, start,
                radius, wheelBase, maxSpeed, modules);
    }

    /** The same robot at another baud rate. */
    public SimRobotConfig withBaud(int newBaud) {
        return new SimRobotConfig(name, newBaud, timing, timeScale, seed, arenaWidth, arenaHeight, obstacles, start,
                radius, wheelBase, maxSpeed, modules);
    }

    /** The same robot with another time scale. */
    public SimRobotConfig withTimeScale(double newScale) {
        return new SimRobotConfig(name, baud, timing, newScale, seed, arenaWidth, arenaHeight, obstacles, start,
                radius, wheelBase, maxSpeed, modules);
    }

    /** Builds world, modules and simulation (not started). */
    Simulation build() {
        World world = new World(arenaWidth, arenaHeight, obstacles, start, radius, wheelBase, maxSpeed);
        List<SimModule> built = new ArrayList<>();
        for (ModuleSpec spec : modules) {
            built.add(spec.build(world, spec.common().faults(seed * 31 + spec.common().address())));
        }
        return new Simulation(world, built, timeScale);
    }
}
