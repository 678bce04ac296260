package robotworld.explorer.demo;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import robotworld.program.JvmOptions;

/** A generated program running in its own JVM from its project (build/classes + lib/*), output to a log file. */
final class ProgramProcess implements AutoCloseable {

    private final String mainClass;
    private final Path log;
    private final Process process;

    private ProgramProcess(String mainClass, Path log, Process process) {
        this.mainClass = mainClass;
        this.log = log;
        this.process = process;
    }

    static ProgramProcess start(Path project, String mainClass, List<String> properties) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString()));
        command.addAll(JvmOptions.LATENCY);
        command.addAll(properties);
        command.addAll(List.of("-cp", project.resolve("build/classes") + File.pathSeparator
                + project.resolve("lib") + File.separator + "*", mainClass));
        Path log = project.resolve("run.log");
        Process process = new ProcessBuilder(command).directory(project.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        return new ProgramProcess(mainClass, log, process);
    }

    String mainClass() {
        return mainClass;
    }

    Path log() {
        return log;
    }

    boolean isAlive() {
        return process.isAlive();
    }

    long pid() {
        return process.pid();
    }

    /** SIGKILL: the program ends at once, nothing of it cleans up. */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor(10, TimeUnit.SECONDS);
    }

    String output() {
        try {
            return Files.readString(log);
        } catch (IOException e) {
            return "";
        }
    }

    /** The last lines of the log, for error messages. */
    String tail(int lines) {
        List<String> all = output().lines().toList();
        return String.join("\n", all.subList(Math.max(0, all.size() - lines), all.size()));
    }

    /** SIGTERM, as Ctrl-C would stop it: its runtime stops its actuators first; after 10 s, SIGKILL. */
    @Override
    public void close() {
        if (process.isAlive()) {
            process.destroy();
            try {
                if (!process.waitFor(10, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                    process.waitFor(5, TimeUnit.SECONDS);
                }
            } catch (InterruptedException e) {
                process.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }
}
