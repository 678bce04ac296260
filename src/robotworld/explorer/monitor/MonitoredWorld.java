package robotworld.explorer.monitor;

import java.util.ArrayList;
import java.util.List;
import org.apache.xmlbeans.XmlObject;
import robotworld.description.EnvModuleListType;
import robotworld.description.ModuleClassName;
import robotworld.description.ModuleListType;
import robotworld.description.ModuleType;
import robotworld.description.RobotWorldDocument;
import robotworld.description.RobotWorldType;
import robotworld.description.X10ModuleType;

/**
 * What a loaded RobotWorld offers to monitor: its name, communication type, space URL and participants with
 * their modules (environments first, as in the description).
 *
 * @param name              the world's name
 * @param communicationType e.g. {@code xvsm}
 * @param spaceUrl          the world's {@code <SpaceURL>}, or null
 * @param participants      environments, then robots
 */
public record MonitoredWorld(String name, String communicationType, String spaceUrl,
                             List<MonitoredParticipant> participants) {

    /** Copies the list. */
    public MonitoredWorld {
        participants = List.copyOf(participants);
    }

    /** Reads a validated world description. */
    public static MonitoredWorld of(RobotWorldDocument document) {
        RobotWorldType world = document.getRobotWorld();
        String type = world.getCommunicationType().toString();
        List<MonitoredParticipant> participants = new ArrayList<>();
        for (EnvModuleListType environment : world.getEnvironmentArray()) {
            String name = environment.getEnvironmentName();
            List<MonitoredModule> modules = new ArrayList<>();
            for (X10ModuleType module : environment.getX10ModuleArray()) {
                modules.add(module(type, name, module.getName(), module));
            }
            for (ModuleType module : environment.getModuleArray()) {
                modules.add(module(type, name, module.getName(), module));
            }
            participants.add(new MonitoredParticipant(name, "environment", modules));
        }
        for (ModuleListType robot : world.getRobotDescriptionArray()) {
            List<MonitoredModule> modules = new ArrayList<>();
            for (ModuleType module : robot.getModuleArray()) {
                modules.add(module(type, robot.getRobotName(), module.getName(), module));
            }
            participants.add(new MonitoredParticipant(robot.getRobotName(), "robot", modules));
        }
        return new MonitoredWorld(world.getWorldName(), type, world.isSetSpaceURL() ? world.getSpaceURL() : null,
                participants);
    }

    /** The world as a {@link robotworld.observe.WorldTap} watches it. */
    public robotworld.observe.WorldLayout layout() {
        return WorldLayouts.of(this);
    }

    /**
     * The same world with only the modules named in {@code names} (a module's {@code <Name>}, or
     * {@code Participant/Name}); participants left without modules are dropped. No names: the whole world.
     *
     * @throws IllegalArgumentException naming what matches no module, and the modules there are
     */
    public MonitoredWorld only(java.util.Collection<String> names) {
        if (names == null || names.isEmpty()) {
            return this;
        }
        java.util.Set<String> unmatched = new java.util.LinkedHashSet<>(names);
        List<MonitoredParticipant> kept = new ArrayList<>();
        for (MonitoredParticipant participant : participants) {
            List<MonitoredModule> modules = new ArrayList<>();
            for (MonitoredModule module : participant.modules()) {
                boolean byName = names.contains(module.moduleName());
                boolean byLabel = names.contains(module.label());
                if (byName || byLabel) {
                    modules.add(module);
                    unmatched.remove(module.moduleName());
                    unmatched.remove(module.label());
                }
            }
            if (!modules.isEmpty()) {
                kept.add(new MonitoredParticipant(participant.name(), participant.kind(), modules));
            }
        }
        if (!unmatched.isEmpty()) {
            List<String> all = participants.stream().flatMap(p -> p.modules().stream()).map(MonitoredModule::label)
                    .toList();
            throw new IllegalArgumentException("no module " + String.join(", ", unmatched) + " in " + name
                    + "; its modules: " + String.join(", ", all));
        }
        return new MonitoredWorld(name, communicationType, spaceUrl, kept);
    }

    /** How many modules all participants have together. */
    public int moduleCount() {
        return participants.stream().mapToInt(participant -> participant.modules().size()).sum();
    }

    private static MonitoredModule module(String type, String participant, String name, XmlObject element) {
        // the class as text: module types added through run-time schemas have no typed getter
        return new MonitoredModule(type, participant, name, ModuleClassName.of(element), element);
    }
}
