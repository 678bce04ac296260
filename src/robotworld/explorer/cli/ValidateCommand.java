package robotworld.explorer.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.apache.xmlbeans.XmlObject;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.description.DescriptionSummary;

/** {@code rwe validate FILE...}: checks descriptions of any kind and lists every error with its position. */
@Command(name = "validate", mixinStandardHelpOptions = true,
        description = {"Validate RobotWorld, robot, environment and module descriptions.",
                "Prints one line per valid file and every error as file:line:column: message.",
                "Exit code 0 when all files are valid, 1 otherwise."})
final class ValidateCommand implements Callable<Integer> {

    @Parameters(arity = "1..*", paramLabel = "FILE", description = "description files to check")
    private List<Path> files;

    @Option(names = "--schemas", paramLabel = "DIR",
            description = "validate against the schemas in DIR (e.g. with added module types) instead of the built-in ones")
    private Path schemaDirectory;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        DescriptionSchemas schemas;
        try {
            schemas = schemaDirectory == null ? DescriptionSchemas.configured()
                    : DescriptionSchemas.fromDirectory(schemaDirectory);
        } catch (DescriptionException e) {
            e.errors().forEach(err::println);
            err.flush();
            return 1;
        }
        int invalid = 0;
        for (Path file : files) {
            try {
                XmlObject document = DescriptionLoader.load(file, null, schemas);
                out.println(file + ": valid " + DescriptionSummary.of(document));
            } catch (DescriptionException e) {
                invalid++;
                for (DescriptionError error : e.errors()) {
                    err.println(error);
                }
            }
        }
        if (files.size() > 1) {
            out.println((files.size() - invalid) + " valid, " + invalid + " invalid");
        }
        out.flush();
        err.flush();
        return invalid == 0 ? 0 : 1;
    }
}
