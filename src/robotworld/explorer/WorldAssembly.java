package robotworld.explorer;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.regex.Pattern;
import robotworld.core.HostNames;
import robotworld.description.DescriptionException;
import robotworld.description.EnvModuleListType;
import robotworld.description.EnvironmentBuilder;
import robotworld.description.EnvironmentBuilder.X10Device;
import robotworld.description.JavaNames;
import robotworld.description.ModuleListType;
import robotworld.description.RobotWorldAssembler;
import robotworld.description.RobotWorldDocument;

/**
 * One world assembly as {@code rwe assemble} and the launcher's "Assemble a world" step do it: robot files,
 * environment files, and optionally an environment written from a list of X10 devices, into a validated RobotWorld.
 */
public final class WorldAssembly {

    /** Where {@code rwe space} serves by default; the world's {@code <SpaceURL>} unless another is given. */
    public static final String DEFAULT_SPACE_URL = "http://localhost:9876/space";

    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");
    private static final Pattern HOST = Pattern.compile("[A-Za-z0-9]([A-Za-z0-9.\\-]*[A-Za-z0-9])?");

    private final String name;
    private String communicationType = "xvsm";
    private String packageName;
    private String spaceUrl = DEFAULT_SPACE_URL;
    private final List<Path> robots = new ArrayList<>();
    private final List<Path> environments = new ArrayList<>();
    private EnvironmentBuilder x10Environment;

    public WorldAssembly(String name) {
        this.name = Objects.requireNonNull(name, "name");
    }

    /** Why {@code name} cannot name a world, environment or robot, in words; null when it can. */
    public static String problemWithName(String name) {
        if (name == null || name.isBlank()) {
            return "a name is needed";
        }
        if (!IDENTIFIER.matcher(name).matches() || name.length() > 64) {
            return "names may contain only letters, digits and _, and may not start with a digit; got '" + name + "'";
        }
        if (JavaNames.isReserved(name)) {
            return "'" + name + "' is a Java keyword; choose another name";
        }
        return null;
    }

    /** This computer's name if it can stand in a description as {@code <Host>}, else localhost. */
    public static String thisComputer() {
        String local = HostNames.thisComputer();
        return local != null && HOST.matcher(local).matches() && local.length() <= 253 ? local : "localhost";
    }

    /** Where the module descriptions are: {@code ModuleDescriptions/} in the RobotWorldExplorer home. */
    public static Path moduleDescriptions() {
        return Path.of(System.getProperty("rwe.home", ".")).resolve("ModuleDescriptions");
    }

    public WorldAssembly communicationType(String type) {
        this.communicationType = Objects.requireNonNull(type, "type");
        return this;
    }

    public WorldAssembly packageName(String name) {
        this.packageName = name == null || name.isBlank() ? null : name.strip();
        return this;
    }

    public WorldAssembly spaceUrl(String url) {
        this.spaceUrl = url == null || url.isBlank() ? null : url.strip();
        return this;
    }

    public WorldAssembly robots(List<Path> files) {
        robots.addAll(files);
        return this;
    }

    public WorldAssembly environments(List<Path> files) {
        environments.addAll(files);
        return this;
    }

    /** An environment written from X10 devices; {@code host} null means this computer. */
    public WorldAssembly x10Environment(String environmentName, String host, String cm11aPort, List<X10Device> devices) {
        EnvironmentBuilder builder = new EnvironmentBuilder(environmentName)
                .host(host == null || host.isBlank() ? thisComputer() : host.strip())
                .cm11aPort(cm11aPort == null || cm11aPort.isBlank() ? EnvironmentBuilder.DEFAULT_CM11A_PORT
                        : cm11aPort.strip())
                .moduleDescriptions(moduleDescriptions());
        devices.forEach(builder::add);
        this.x10Environment = builder;
        return this;
    }

    /** The validated world; every error of every part, each with its file, line and column where known. */
    public RobotWorldDocument assemble() throws DescriptionException {
        RobotWorldAssembler assembler = new RobotWorldAssembler(name).communicationType(communicationType)
                .packageName(packageName).spaceUrl("none".equals(communicationType) ? null : spaceUrl);
        environments.forEach(assembler::addEnvironment);
        if (x10Environment != null) {
            assembler.addEnvironment(x10Environment.build());
        }
        robots.forEach(assembler::addRobot);
        return assembler.assemble();
    }

    /** Writes the world atomically. */
    public static void write(RobotWorldDocument world, Path file) throws IOException {
        RobotWorldAssembler.write(world, file);
    }

    /** The viewpoints a project can be generated for: every participant, and {@code external} with a space. */
    public static List<String> viewpoints(RobotWorldDocument world) {
        List<String> names = new ArrayList<>();
        for (EnvModuleListType environment : world.getRobotWorld().getEnvironmentArray()) {
            names.add(environment.getEnvironmentName());
        }
        for (ModuleListType robot : world.getRobotWorld().getRobotDescriptionArray()) {
            names.add(robot.getRobotName());
        }
        if ("xvsm".equals(world.getRobotWorld().getCommunicationType().toString())) {
            names.add(FrameworkGenerator.EXTERNAL);
        }
        return names;
    }
}
