package robotworld.description;

import org.apache.xmlbeans.XmlObject;

/** One-line human summaries of loaded descriptions, e.g. for {@code rwe validate}. */
public final class DescriptionSummary {

    private DescriptionSummary() {
    }

    public static String of(XmlObject document) {
        if (document instanceof RobotWorldDocument doc) {
            RobotWorldType world = doc.getRobotWorld();
            int modules = 0;
            for (EnvModuleListType environment : world.getEnvironmentArray()) {
                modules += environment.sizeOfX10ModuleArray() + environment.sizeOfModuleArray();
            }
            for (ModuleListType robot : world.getRobotDescriptionArray()) {
                modules += robot.sizeOfModuleArray();
            }
            return "RobotWorld '" + world.getWorldName() + "' (" + world.getCommunicationType() + "): "
                    + count(world.sizeOfEnvironmentArray(), "environment") + ", "
                    + count(world.sizeOfRobotDescriptionArray(), "robot") + ", " + count(modules, "module");
        }
        if (document instanceof RobotDescriptionDocument doc) {
            ModuleListType robot = doc.getRobotDescription();
            return "robot '" + robot.getRobotName() + "': " + count(robot.sizeOfModuleArray(), "module");
        }
        if (document instanceof EnvironmentDocument doc) {
            EnvModuleListType environment = doc.getEnvironment();
            return "environment '" + environment.getEnvironmentName() + "': "
                    + count(environment.sizeOfX10ModuleArray(), "X10 module") + ", "
                    + count(environment.sizeOfModuleArray(), "bus module");
        }
        if (document instanceof ModuleDescriptionDocument doc) {
            ModuleDescriptionType module = doc.getModuleDescription();
            return "module description " + module.getNodeID() + " (" + ModuleClassName.of(module) + ")";
        }
        return document.schemaType().toString();
    }

    private static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }
}
