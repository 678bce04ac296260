package robotworld.explorer.generator;

import java.io.IOException;
import java.io.ByteArrayOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

/** Test helper: inspects, edits and compiles a generated project. */
public final class GeneratedProject {

    public static final String CONTROL_BEGIN = "// >>> control logic begins here";
    public static final String CONTROL_END = "// <<< control logic ends here";

    private final Path root;

    public GeneratedProject(Path root) {
        this.root = root;
    }

    public Path root() {
        return root;
    }

    public List<Path> sources() throws IOException {
        try (Stream<Path> files = Files.walk(root.resolve("src"))) {
            return files.filter(f -> f.toString().endsWith(".java")).sorted().collect(Collectors.toList());
        }
    }

    public List<Path> libraries() throws IOException {
        try (Stream<Path> files = Files.list(root.resolve("lib"))) {
            return files.filter(f -> f.toString().endsWith(".jar"))
                    .filter(f -> !FrameworkLibraries.isAttachment(f.getFileName().toString()))
                    .sorted().collect(Collectors.toList());
        }
    }

    public String read(String relative) throws IOException {
        return Files.readString(root.resolve(relative));
    }

    /** Puts {@code snippet} between the markers of the control program in {@code mainSource}, as a user does. */
    public void insertControlLogic(String mainSource, String snippet) throws IOException {
        Path file = root.resolve(mainSource);
        String source = Files.readString(file);
        int begin = source.indexOf(CONTROL_BEGIN);
        int end = source.indexOf(CONTROL_END);
        if (begin < 0 || end < begin) {
            throw new IllegalStateException(mainSource + " has no marked place for control logic");
        }
        int lineEnd = source.indexOf('\n', begin) + 1;
        int endLine = source.lastIndexOf('\n', end) + 1;
        Files.writeString(file, source.substring(0, lineEnd) + snippet + (snippet.endsWith("\n") ? "" : "\n")
                + source.substring(endLine));
    }

    /** Compiles src/ against lib/ with the JDK's compiler; returns the diagnostics, empty when it compiled. */
    public String compile(Path classes, Path... extraClassPath) throws IOException {
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        List<Path> classPath = new ArrayList<>(libraries());
        classPath.addAll(List.of(extraClassPath));
        List<String> arguments = new ArrayList<>(List.of("-d", classes.toString(), "-encoding", "UTF-8",
                "-Xlint:none", "-cp", classPath.stream().map(Path::toString)
                        .collect(Collectors.joining(java.io.File.pathSeparator))));
        sources().forEach(source -> arguments.add(source.toString()));
        ByteArrayOutputStream diagnostics = new ByteArrayOutputStream();
        int result = compiler.run(null, null, diagnostics, arguments.toArray(String[]::new));
        return result == 0 ? "" : "javac failed:\n" + diagnostics;
    }

    /** Builds the project with its own build.xml and plain Ant ({@code ant compile}), as a user would. */
    public void antCompile() throws IOException, InterruptedException {
        String antHome = System.getProperty("rwe.ant.home");
        String ant = antHome == null ? "ant" : Path.of(antHome, "bin", "ant").toString();
        Path log = root.resolve("ant.log");
        Process build = new ProcessBuilder(ant, "-q", "compile").directory(root.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        if (!build.waitFor(180, java.util.concurrent.TimeUnit.SECONDS)) {
            build.destroyForcibly();
            throw new IllegalStateException("ant compile did not finish in " + root);
        }
        if (build.exitValue() != 0 || !Files.isDirectory(root.resolve("build/classes"))) {
            throw new IllegalStateException("ant compile failed in " + root + ":\n" + Files.readString(log));
        }
    }
}
