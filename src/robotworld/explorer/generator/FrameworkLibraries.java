package robotworld.explorer.generator;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * The jars a generated project needs in its {@code lib/}: {@code robotworld-runtime.jar} (module interfaces,
 * space client, XVSM proxies, hardware proxies) with its sources and javadoc jars, and the libraries it runs on. The build puts exactly these into
 * {@code build/dist/framework/}; an installed RobotWorldExplorer has them in {@code framework/} beside its jar.
 */
public final class FrameworkLibraries {

    /** Overrides where the framework jars are taken from. */
    public static final String DIRECTORY_PROPERTY = "rwe.framework.dir";
    static final String RUNTIME_JAR = "robotworld-runtime.jar";

    private FrameworkLibraries() {
    }

    /** The framework directory: the override, else {@code framework/} beside the running jar or in the build. */
    public static Path defaultDirectory() {
        String configured = System.getProperty(DIRECTORY_PROPERTY);
        if (configured != null && !configured.isBlank()) {
            return Path.of(configured);
        }
        try {
            Path codeSource = Path.of(FrameworkLibraries.class.getProtectionDomain().getCodeSource().getLocation()
                    .toURI());
            if (codeSource.toString().endsWith(".jar")) {
                return codeSource.resolveSibling("framework");
            }
        } catch (URISyntaxException | SecurityException | NullPointerException e) {
            // fall through to the build layout
        }
        return Path.of(System.getProperty("rwe.home", ".")).resolve("build/dist/framework");
    }

    /** Whether a jar is a sources or javadoc jar: attached to another for the IDE, never on a class path. */
    public static boolean isAttachment(String jarName) {
        return jarName.endsWith("-sources.jar") || jarName.endsWith("-javadoc.jar");
    }

    /** The jars to compile and run against: {@link #in} without the attachments. */
    public static List<Path> classPath(Path directory) throws GenerationException {
        return in(directory).stream().filter(jar -> !isAttachment(jar.getFileName().toString())).toList();
    }

    /** The jars in {@code directory} (attachments included), sorted; fails when the runtime jar is not among them. */
    public static List<Path> in(Path directory) throws GenerationException {
        if (!Files.isRegularFile(directory.resolve(RUNTIME_JAR))) {
            throw new GenerationException("no " + RUNTIME_JAR + " in " + directory.toAbsolutePath()
                    + ": build it with ./antw dist, or point -D" + DIRECTORY_PROPERTY + " at the framework jars");
        }
        try (Stream<Path> files = Files.list(directory)) {
            return files.filter(f -> f.getFileName().toString().endsWith(".jar")).sorted().toList();
        } catch (IOException e) {
            throw new GenerationException("cannot list " + directory + ": " + e.getMessage(), e);
        }
    }
}
