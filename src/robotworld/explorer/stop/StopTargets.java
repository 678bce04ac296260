package robotworld.explorer.stop;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.MonitoredParticipant;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.safety.Actuator;
import robotworld.safety.WorldStop;

/**
 * The modules a stop of a world is for, with whether each is an actuator. Found by the naming convention: a module
 * of class {@code C} in a world of type {@code t} is an actuator when {@code robotworld.<t>.<T>CLocal} implements
 * {@link Actuator}; a class that cannot be found is taken for an actuator, so that a module type this computer does
 * not know is never reported as safely stopped when it did not answer.
 */
public final class StopTargets {

    private StopTargets() {
    }

    /** Every module of the world, environments first, as in the description. */
    public static List<WorldStop.Target> of(MonitoredWorld world) {
        List<WorldStop.Target> targets = new ArrayList<>();
        for (MonitoredParticipant participant : world.participants()) {
            for (MonitoredModule module : participant.modules()) {
                targets.add(new WorldStop.Target(module.participant(), module.moduleName(),
                        isActuator(module.communicationType(), module.moduleClass())));
            }
        }
        return targets;
    }

    /** Whether modules of {@code moduleClass} are actuators in a world of {@code communicationType}. */
    public static boolean isActuator(String communicationType, String moduleClass) {
        String local = "robotworld." + communicationType.toLowerCase(Locale.ROOT) + "."
                + communicationType.toUpperCase(Locale.ROOT) + moduleClass + "Local";
        try {
            return Actuator.class.isAssignableFrom(Class.forName(local, false, StopTargets.class.getClassLoader()));
        } catch (ClassNotFoundException | LinkageError e) {
            return true;
        }
    }
}
