package robotworld.explorer.generator;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

/**
 * A generated project.
 *
 * @param destination the project directory
 * @param mainClass   the qualified name of the class with {@code main} (the viewpoint's program)
 * @param files       every file written, under {@code destination}
 * @param elapsed     how long generation took
 */
public record GenerationResult(Path destination, String mainClass, List<Path> files, Duration elapsed) {

    /** The source file of the main class, where the control program goes. */
    public Path mainSource() {
        return destination.resolve("src/" + mainClass.replace('.', '/') + ".java");
    }
}
