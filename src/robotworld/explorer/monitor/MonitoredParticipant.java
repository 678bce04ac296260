package robotworld.explorer.monitor;

import java.util.List;

/**
 * A robot or environment with the modules to monitor.
 *
 * @param name    the robot's or environment's name
 * @param kind    {@code robot} or {@code environment}
 * @param modules its modules, in description order
 */
public record MonitoredParticipant(String name, String kind, List<MonitoredModule> modules) {

    /** Copies the list. */
    public MonitoredParticipant {
        modules = List.copyOf(modules);
    }
}
