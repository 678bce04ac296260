package robotworld.explorer.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.FrameworkGenerator;
import robotworld.explorer.generator.ControlRegion;
import robotworld.explorer.generator.GenerationException;
import robotworld.explorer.generator.GenerationResult;
import robotworld.explorer.generator.RunInstructions;

/** {@code rwe generate WORLD --viewpoint NAME|external --out DIR}: a ready Ant + Eclipse project. */
@Command(name = "generate", mixinStandardHelpOptions = true,
        description = {"Generate the control framework of one viewpoint of a RobotWorld: build.xml, one class per",
                "participant, the framework jars in lib/, and Eclipse project files.",
                "Prints the command that builds and runs it with plain Ant (ant run -Drwe.space.url=... -Drwe.port...)."})
final class GenerateCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "WORLD", description = "the RobotWorld description")
    private Path world;

    @Option(names = "--viewpoint", required = true, paramLabel = "NAME",
            description = "the participant whose computer runs the program, or 'external' for one that owns"
                    + " no hardware")
    private String viewpoint;

    @Option(names = "--package", paramLabel = "P",
            description = "Java package of the generated classes (default: the world's PackageName)")
    private String packageName;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "the project directory to create")
    private Path out;

    @Option(names = "--force", description = "replace DIR if it exists and is not empty")
    private boolean force;

    @Option(names = "--control", paramLabel = "FILE",
            description = "put the Java statements in FILE between the markers of the main class's control() method"
                    + " (a control program kept apart from the generated code)")
    private Path controlFile;

    @Option(names = "--schemas", paramLabel = "DIR",
            description = "validate against the schemas in DIR (e.g. with added module types) instead of the built-in ones")
    private Path schemaDirectory;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        try {
            // read before anything is written: a missing file leaves no half-made project
            String controlProgram = controlFile == null ? null : Files.readString(controlFile, StandardCharsets.UTF_8);
            DescriptionSchemas schemas = schemaDirectory == null ? DescriptionSchemas.configured()
                    : DescriptionSchemas.fromDirectory(schemaDirectory);
            err.printf("validating %s%n", world);
            RobotWorldDocument loaded = DescriptionLoader.loadWorld(world, schemas);
            GenerationResult result = new FrameworkGenerator().generate(loaded, viewpoint, packageName, this.out,
                    force, (done, total, step) -> {
                        if (!step.startsWith("copying ") || step.contains("robotworld-runtime")) {
                            err.printf("[%d/%d] %s%n", done, total, step);
                        }
                    });
            out.printf("generated %s (%d files, %d ms), main class %s%n", result.destination(),
                    result.files().size(), result.elapsed().toMillis(), result.mainClass());
            if (controlProgram != null) {
                ControlRegion.replace(result.mainSource(), controlProgram);
                out.println("put the control program of " + controlFile + " into "
                        + result.destination().relativize(result.mainSource()) + "; run it:");
            } else {
                out.println("write your control program in " + result.destination().relativize(result.mainSource())
                        + ", between the markers of control(); then run it:");
            }
            out.println("  " + RunInstructions.command(loaded, viewpoint, result.destination()));
            out.println("(the space and ports are the description's: change them there, e.g."
                    + " -Drwe.port.NAME.bus=tcp://127.0.0.1:5020 for a simulated robot)");
            return 0;
        } catch (DescriptionException e) {
            e.errors().stream().map(DescriptionError::toString).forEach(err::println);
            return 1;
        } catch (GenerationException e) {
            err.println("rwe generate: " + e.getMessage());
            return 1;
        } finally {
            out.flush();
            err.flush();
        }
    }
}
