package robotworld.description;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.apache.xmlbeans.XmlObject;

/**
 * The rules a schema cannot express, checked after schema validation:
 * <ul>
 *   <li>names that become Java identifiers are not Java keywords and do not shadow classes the generated code
 *       uses;</li>
 *   <li>participant names are unique in a world, module names unique in a participant, and the space container
 *       names built from them ({@code <Participant><Module>REQUEST}) are unique;</li>
 *   <li>bus addresses (NodeNumber) are unique on each bus;</li>
 *   <li>an environment with robot-bus modules names the bus port and the bus class.</li>
 * </ul>
 */
final class DescriptionRules {

    /** Class names the generated code refers to; a participant class of the same name would shadow them. */
    private static final Set<String> RESERVED_CLASS_NAMES = Set.of(
            "Object", "String", "System", "Thread", "Math", "Exception", "RuntimeException", "Integer", "Long",
            "Double", "Boolean", "Runtime", "Override", "InterruptedException",
            "MotorModule", "ServoModule", "BumperModule", "IRDistanceModule", "X10LampModule",
            "X10ApplianceModule", "RS485Bus");

    /** Generated code names module fields <Class><n>, e.g. MotorModule1. */
    private static final java.util.regex.Pattern GENERATED_FIELD_NAME =
            java.util.regex.Pattern.compile("[A-Za-z0-9_]*Module[0-9]+");

    private static final Set<String> GENERATED_CONSTANTS = Set.of("NAME", "HOST", "SPACE_URL");

    private final String source;
    private final List<DescriptionError> errors = new ArrayList<>();

    private DescriptionRules(String source) {
        this.source = source;
    }

    static List<DescriptionError> check(XmlObject document, String source) {
        DescriptionRules rules = new DescriptionRules(source);
        if (document instanceof RobotWorldDocument world) {
            rules.checkWorld(world.getRobotWorld());
        } else if (document instanceof RobotDescriptionDocument robot) {
            rules.checkRobot(robot.getRobotDescription());
        } else if (document instanceof EnvironmentDocument environment) {
            rules.checkEnvironment(environment.getEnvironment());
        }
        return rules.errors;
    }

    private void checkWorld(RobotWorldType world) {
        identifier(world.xgetWorldName(), world.getWorldName(), "world name");
        if (world.isSetPackageName()) {
            for (String segment : world.getPackageName().split("\\.")) {
                if (JavaNames.isReserved(segment)) {
                    error(world.xgetPackageName(), "package name '" + world.getPackageName()
                            + "' contains the Java keyword '" + segment + "'");
                }
            }
        }
        Map<String, XmlObject> participants = new HashMap<>();
        Map<String, ContainerOwner> containers = new HashMap<>();
        for (EnvModuleListType environment : world.getEnvironmentArray()) {
            unique(participants, environment.getEnvironmentName(), environment.xgetEnvironmentName(),
                    "participant name", "this world");
            checkEnvironment(environment);
            containerNames(containers, environment.getEnvironmentName(), environment.getX10ModuleArray());
            containerNames(containers, environment.getEnvironmentName(), environment.getModuleArray());
        }
        for (ModuleListType robot : world.getRobotDescriptionArray()) {
            unique(participants, robot.getRobotName(), robot.xgetRobotName(), "participant name", "this world");
            checkRobot(robot);
            containerNames(containers, robot.getRobotName(), robot.getModuleArray());
        }
    }

    private void checkRobot(ModuleListType robot) {
        participantName(robot.xgetRobotName(), robot.getRobotName());
        moduleNames(robot.getModuleArray(), robot.getRobotName());
        busAddresses(robot.getModuleArray(), robot.getRobotName());
    }

    private void checkEnvironment(EnvModuleListType environment) {
        String name = environment.getEnvironmentName();
        participantName(environment.xgetEnvironmentName(), name);
        List<XmlObject> modules = new ArrayList<>(List.of(environment.getX10ModuleArray()));
        modules.addAll(List.of(environment.getModuleArray()));
        moduleNames(modules.toArray(XmlObject[]::new), name);
        ModuleType[] busModules = environment.getModuleArray();
        if (busModules.length > 0) {
            if (!environment.isSetBusPort()) {
                error(busModules[0], "environment '" + name + "' has robot-bus modules but no <BusPort>");
            }
            if (!environment.isSetTalkToBusClass()) {
                error(busModules[0], "environment '" + name + "' has robot-bus modules but no <TalkToBusClass>");
            }
        }
        busAddresses(busModules, name);
    }

    private void participantName(XmlObject at, String name) {
        identifier(at, name, "participant name");
        if (GENERATED_FIELD_NAME.matcher(name).matches() || GENERATED_CONSTANTS.contains(name)) {
            error(at, "participant name '" + name + "' has the form of a generated field name (<Class><n>,"
                    + " NAME, HOST, SPACE_URL); choose another name");
        }
        if (RESERVED_CLASS_NAMES.contains(name)) {
            error(at, "participant name '" + name + "' would hide the class " + name
                    + " in generated code; choose another name");
        }
    }

    private void identifier(XmlObject at, String name, String what) {
        if (JavaNames.isReserved(name)) {
            error(at, what + " '" + name + "' is a Java keyword and cannot name a class or package");
        }
    }

    private void moduleNames(XmlObject[] modules, String participant) {
        Map<String, XmlObject> seen = new HashMap<>();
        for (XmlObject module : modules) {
            String name = module instanceof ModuleType bus ? bus.getName() : ((X10ModuleType) module).getName();
            unique(seen, name, module, "module name", "'" + participant + "'");
        }
    }

    private void busAddresses(ModuleType[] modules, String participant) {
        Map<String, XmlObject> seen = new HashMap<>();
        for (ModuleType module : modules) {
            unique(seen, Integer.toString(module.getNodeNumber()), module.xgetNodeNumber(),
                    "bus address (NodeNumber)", "the bus of '" + participant + "'");
        }
    }

    /**
     * Container names are participant + module name, so different pairs can spell the same name
     * ("Ab" + "cX" and "A" + "bcX"). Same-participant duplicates are already reported as duplicate modules.
     */
    private void containerNames(Map<String, ContainerOwner> seen, String participant, XmlObject[] modules) {
        for (XmlObject module : modules) {
            String name = module instanceof ModuleType bus ? bus.getName() : ((X10ModuleType) module).getName();
            ContainerOwner earlier = seen.putIfAbsent(participant + name, new ContainerOwner(participant, module));
            if (earlier != null && !earlier.participant().equals(participant)) {
                error(module, "space container name '" + participant + name + "REQUEST' is also built by"
                        + " participant '" + earlier.participant() + "' at line " + SourcePositions.of(earlier.module())[0]
                        + "; rename one of them");
            }
        }
    }

    private record ContainerOwner(String participant, XmlObject module) {
    }

    private void unique(Map<String, XmlObject> seen, String value, XmlObject at, String what, String where) {
        XmlObject earlier = seen.putIfAbsent(value, at);
        if (earlier != null) {
            int line = SourcePositions.of(earlier)[0];
            error(at, "duplicate " + what + " '" + value + "' in " + where
                    + (line > 0 ? " (first used at line " + line + ")" : ""));
        }
    }

    private void error(XmlObject at, String message) {
        int[] position = SourcePositions.of(at);
        errors.add(new DescriptionError(source, position[0], position[1], message));
    }
}
