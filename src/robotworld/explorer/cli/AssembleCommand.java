package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionSummary;
import robotworld.description.EnvironmentBuilder;
import robotworld.description.EnvironmentBuilder.X10Device;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.WorldAssembly;

/**
 * {@code rwe assemble --robot R.xml... [--environment E.xml] [--x10 A3=appliance:Lamp ...] --name W --out W.xml}:
 * a RobotWorld from robot descriptions (as {@code rwe explore} writes them) and environments, without editing XML.
 */
@Command(name = "assemble", mixinStandardHelpOptions = true,
        description = {"Assemble a RobotWorld from robot descriptions (written by rwe explore) and environments.",
                "An environment with X10 devices can be given as a file (--environment) or written from --x10 options",
                "(with --environment-name, --environment-host and --cm11a-port).",
                "Then: rwe generate WORLD --viewpoint NAME --out DIR."})
final class AssembleCommand implements Callable<Integer> {

    @Option(names = "--robot", required = true, paramLabel = "FILE", description = "a robot description (repeat for"
            + " more robots)")
    private List<Path> robots = new ArrayList<>();

    @Option(names = "--environment", paramLabel = "FILE", description = "an environment description (repeatable)")
    private List<Path> environments = new ArrayList<>();

    @Option(names = "--x10", paramLabel = "ADDRESS=KIND[:NAME]", split = ",",
            description = "an X10 device of a new environment: A3=appliance, B1=lamp:Ceiling-Lamp (repeatable)")
    private List<String> x10 = new ArrayList<>();

    @Option(names = "--environment-name", paramLabel = "NAME", defaultValue = "Room",
            description = "the name of the environment written from --x10 (default: ${DEFAULT-VALUE})")
    private String environmentName;

    @Option(names = "--environment-host", paramLabel = "HOST",
            description = "the computer of that environment, which runs its program (default: this computer)")
    private String environmentHost;

    @Option(names = "--cm11a-port", paramLabel = "PORT", defaultValue = EnvironmentBuilder.DEFAULT_CM11A_PORT,
            description = "the serial port of its CM11A, or tcp://HOST:PORT (default: ${DEFAULT-VALUE}; programs can"
                    + " override it with -Drwe.port.NAME.x10=PORT)")
    private String cm11aPort;

    @Option(names = "--name", required = true, paramLabel = "NAME", description = "the world's name")
    private String name;

    @Option(names = "--package", paramLabel = "P", description = "Java package of generated code (default: the"
            + " world's name in lower case)")
    private String packageName;

    @Option(names = "--space", paramLabel = "URL[,URL...]", defaultValue = WorldAssembly.DEFAULT_SPACE_URL,
            description = "where the space server runs, or the servers of a clustered space separated by commas "
                    + "(default: ${DEFAULT-VALUE}, what rwe space serves)")
    private String spaceUrl;

    @Option(names = "--communication", paramLabel = "xvsm|none", defaultValue = "xvsm",
            description = "xvsm: programs share modules through the space; none: one robot, no space"
                    + " (default: ${DEFAULT-VALUE})")
    private String communication;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "where to write the world")
    private Path out;

    @Option(names = "--force", description = "replace FILE if it exists")
    private boolean force;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter stdout = spec.commandLine().getOut();
        PrintWriter stderr = spec.commandLine().getErr();
        usage(WorldAssembly.problemWithName(name), "--name");
        if (Files.exists(out) && !force) {
            throw new ParameterException(spec.commandLine(), out + " exists; choose another --out or add --force to"
                    + " replace it");
        }
        List<X10Device> devices = new ArrayList<>();
        for (String device : x10) {
            try {
                devices.add(X10Device.parse(device));
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), "--x10 " + device + ": " + e.getMessage());
            }
        }
        WorldAssembly assembly = new WorldAssembly(name).communicationType(communication).packageName(packageName)
                .spaceUrl(spaceUrl).robots(robots).environments(environments);
        if (!devices.isEmpty()) {
            usage(WorldAssembly.problemWithName(environmentName), "--environment-name");
            assembly.x10Environment(environmentName, environmentHost, cm11aPort, devices);
        }
        RobotWorldDocument world;
        try {
            world = assembly.assemble();
        } catch (DescriptionException e) {
            e.errors().stream().map(DescriptionError::toString).forEach(stderr::println);
            return 1;
        }
        WorldAssembly.write(world, out);
        stdout.println("wrote " + out + ": " + DescriptionSummary.of(world));
        stdout.println("next: rwe generate " + out + " --viewpoint NAME --out DIR   (NAME: "
                + String.join(", ", WorldAssembly.viewpoints(world)) + ")");
        return 0;
    }

    private void usage(String problem, String option) {
        if (problem != null) {
            throw new ParameterException(spec.commandLine(), option + ": " + problem);
        }
    }
}
