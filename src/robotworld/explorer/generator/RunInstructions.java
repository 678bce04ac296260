package robotworld.explorer.generator;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robotworld.description.EnvModuleListType;
import robotworld.description.ModuleListType;
import robotworld.description.RobotWorldDocument;
import robotworld.description.RobotWorldType;

/**
 * The exact command that runs a generated project, with every run-time setting the viewpoint needs spelled out
 * (the space, and the ports of the viewpoint's hardware, as the description gives them), so a user can copy it
 * and change what differs on their computer.
 */
public final class RunInstructions {

    private RunInstructions() {
    }

    /** {@code cd DIR && ant run -Drwe.space.url=... -Drwe.port.P.bus=...}. */
    public static String command(RobotWorldDocument world, String viewpoint, Path project) {
        StringBuilder command = new StringBuilder("cd ").append(shellWord(project.toString())).append(" && ant run");
        properties(world, viewpoint).forEach(p -> command.append(" -D").append(shellWord(p)));
        return command.toString();
    }

    /** {@code rwe.space.url=...}, {@code rwe.port.<viewpoint>.bus=...}, {@code rwe.port.<viewpoint>.x10=...}. */
    public static List<String> properties(RobotWorldDocument world, String viewpoint) {
        RobotWorldType description = world.getRobotWorld();
        List<String> properties = new ArrayList<>();
        if ("xvsm".equals(description.getCommunicationType().toString())) {
            properties.add("rwe.space.url=" + (description.isSetSpaceURL() ? description.getSpaceURL()
                    : "http://HOST:9876/space"));
        }
        for (EnvModuleListType environment : description.getEnvironmentArray()) {
            if (environment.getEnvironmentName().equals(viewpoint)) {
                if (environment.sizeOfModuleArray() > 0) {
                    properties.add(port(viewpoint, "bus", environment.isSetBusPort() ? environment.getBusPort() : null));
                }
                if (environment.sizeOfX10ModuleArray() > 0) {
                    properties.add(port(viewpoint, "x10", environment.getCOMPort()));
                }
            }
        }
        for (ModuleListType robot : description.getRobotDescriptionArray()) {
            if (robot.getRobotName().equals(viewpoint) && robot.sizeOfModuleArray() > 0) {
                properties.add(port(viewpoint, "bus", robot.isSetCOMPort() ? robot.getCOMPort() : null));
            }
        }
        return properties;
    }

    private static String port(String participant, String kind, String fromDescription) {
        return "rwe.port." + participant + "." + kind + "=" + (fromDescription == null ? "PORT" : fromDescription);
    }

    /** Quoted for a POSIX shell when it holds anything but safe characters. */
    static String shellWord(String word) {
        if (word.matches("[A-Za-z0-9_@%+=:,./\\-\\[\\]]+")) {
            return word;
        }
        return "'" + word.replace("'", "'\\''") + "'";
    }
}
