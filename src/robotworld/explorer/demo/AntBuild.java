package robotworld.explorer.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/** Builds a generated project with its own build.xml and plain Ant ({@code ant -q compile}), as a user would. */
final class AntBuild {

    private AntBuild() {
    }

    /** The ant command: rwe.ant.home/bin/ant when set (./antw sets it), else {@code ant} on the PATH. */
    static String antCommand() {
        String antHome = System.getProperty("rwe.ant.home");
        return antHome == null || antHome.isBlank() ? "ant" : Path.of(antHome, "bin", "ant").toString();
    }

    static void compile(Path project) throws IOException, InterruptedException {
        Path log = project.resolve("ant.log");
        Process build = new ProcessBuilder(antCommand(), "-q", "compile").directory(project.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        if (!build.waitFor(180, TimeUnit.SECONDS)) {
            build.destroyForcibly();
            throw new IOException("ant compile did not finish in 180 s in " + project);
        }
        if (build.exitValue() != 0 || !Files.isDirectory(project.resolve("build/classes"))) {
            throw new IOException("ant compile failed in " + project + " (see " + log + "):\n" + Files.readString(log));
        }
    }
}
