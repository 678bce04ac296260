package robotworld.description;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.apache.xmlbeans.XmlOptions;

/**
 * Assembles a RobotWorld from separate robot and environment description files: the usual way a world comes
 * about (robots are written by bus exploration, environments by hand).
 *
 * <pre>{@code
 * RobotWorldDocument world = new RobotWorldAssembler("LabWorld")
 *         .communicationType("xvsm")
 *         .spaceUrl("http://localhost:9876/space")
 *         .addEnvironment(Path.of("room.xml"))
 *         .addRobot(Path.of("robot1.xml"))
 *         .assemble();
 * }</pre>
 *
 * Every part is loaded and validated on its own (errors name the part's file), then the assembled world is
 * validated as a whole (duplicate participant names, clashing container names).
 */
public final class RobotWorldAssembler {

    private final String worldName;
    private String communicationType = "xvsm";
    private String packageName;
    private String spaceUrl;
    private final List<Path> environments = new ArrayList<>();
    private final List<EnvironmentDocument> builtEnvironments = new ArrayList<>();
    private final List<Path> robots = new ArrayList<>();

    public RobotWorldAssembler(String worldName) {
        this.worldName = Objects.requireNonNull(worldName, "worldName");
    }

    /** {@code xvsm} (default) or {@code none}. */
    public RobotWorldAssembler communicationType(String type) {
        this.communicationType = Objects.requireNonNull(type, "type");
        return this;
    }

    public RobotWorldAssembler packageName(String name) {
        this.packageName = name;
        return this;
    }

    public RobotWorldAssembler spaceUrl(String url) {
        this.spaceUrl = url;
        return this;
    }

    public RobotWorldAssembler addEnvironment(Path environmentFile) {
        environments.add(Objects.requireNonNull(environmentFile, "environmentFile"));
        return this;
    }

    /** Adds an environment built in memory, e.g. by {@link EnvironmentBuilder}. */
    public RobotWorldAssembler addEnvironment(EnvironmentDocument environment) {
        builtEnvironments.add(Objects.requireNonNull(environment, "environment"));
        return this;
    }

    public RobotWorldAssembler addRobot(Path robotFile) {
        robots.add(Objects.requireNonNull(robotFile, "robotFile"));
        return this;
    }

    /**
     * Loads every part and returns the validated world. Errors of all parts are reported together; an error of the
     * world as a whole (a participant name used twice) is reported at its place in the part's file.
     */
    public RobotWorldDocument assemble() throws DescriptionException {
        List<DescriptionError> errors = new ArrayList<>();
        List<Part<EnvModuleListType>> loadedEnvironments = new ArrayList<>();
        List<Part<ModuleListType>> loadedRobots = new ArrayList<>();
        for (Path file : environments) {
            try {
                loadedEnvironments.add(new Part<>(DescriptionLoader.loadEnvironment(file).getEnvironment(),
                        file.toString()));
            } catch (DescriptionException e) {
                errors.addAll(e.errors());
            }
        }
        for (EnvironmentDocument built : builtEnvironments) {
            loadedEnvironments.add(new Part<>(built.getEnvironment(), null));
        }
        for (Path file : robots) {
            try {
                loadedRobots.add(new Part<>(DescriptionLoader.loadRobot(file).getRobotDescription(), file.toString()));
            } catch (DescriptionException e) {
                errors.addAll(e.errors());
            }
        }
        if (robots.isEmpty()) {
            errors.add(new DescriptionError(worldName, 0, 0, "a RobotWorld needs at least one robot"));
        }
        if (CommunicationTypeType.Enum.forString(communicationType) == null) {
            errors.add(new DescriptionError(worldName, 0, 0,
                    "unknown communication type '" + communicationType + "' (expected xvsm or none)"));
        }
        if (!errors.isEmpty()) {
            throw new DescriptionException(errors);
        }

        RobotWorldDocument document = RobotWorldDocument.Factory.newInstance();
        RobotWorldType world = document.addNewRobotWorld();
        world.setWorldName(worldName);
        world.setCommunicationType(CommunicationTypeType.Enum.forString(communicationType));
        if (packageName != null) {
            world.setPackageName(packageName);
        }
        if (spaceUrl != null) {
            world.setSpaceURL(spaceUrl);
        }
        for (Part<EnvModuleListType> environment : loadedEnvironments) {
            EnvModuleListType copy = world.addNewEnvironment();
            copy.set(environment.element());
            SourcePositions.copy(environment.element(), copy, environment.source());
        }
        for (Part<ModuleListType> robot : loadedRobots) {
            ModuleListType copy = world.addNewRobotDescription();
            copy.set(robot.element());
            SourcePositions.copy(robot.element(), copy, robot.source());
        }
        DescriptionLoader.validate(document, "assembled world '" + worldName + "'");
        return document;
    }

    /** A loaded part and the file it came from (null when it was built in memory). */
    private record Part<T extends org.apache.xmlbeans.XmlObject>(T element, String source) {
    }

    /** Writes a description as indented XML, atomically: a reader never sees a half-written file. */
    public static void write(org.apache.xmlbeans.XmlObject document, Path file) throws IOException {
        Path target = file.toAbsolutePath();
        Files.createDirectories(target.getParent());
        Path temporary = Files.createTempFile(target.getParent(), ".rwe-", ".xml.tmp");
        try {
            XmlOptions options = new XmlOptions().setSavePrettyPrint().setSavePrettyPrintIndent(2)
                    .setSaveAggressiveNamespaces().setUseDefaultNamespace().setCharacterEncoding("UTF-8");
            document.save(temporary.toFile(), options);
            Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }
}
