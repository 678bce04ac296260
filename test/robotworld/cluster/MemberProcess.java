package robotworld.cluster;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A {@link ScriptedMember} in a child process (optionally run through a prefix such as {@code ip netns exec NS}):
 * send it a command, read its answer line. {@link #kill()} is {@code kill -9}.
 */
final class MemberProcess implements AutoCloseable {

    private final Process process;
    private final Writer commands;
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
    private final String address;

    private MemberProcess(Process process, Duration startWithin) throws IOException {
        this.process = process;
        this.commands = new OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8);
        Thread reader = new Thread(() -> {
            try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                String line;
                while ((line = in.readLine()) != null) {
                    if (line.startsWith("ok") || line.startsWith("error") || line.startsWith("ready")) {
                        lines.add(line);
                    }
                }
            } catch (IOException e) {
                // the process died
            }
            lines.add("exited");
        }, "member-process-reader");
        reader.setDaemon(true);
        reader.start();
        String ready = next(startWithin);
        if (!ready.startsWith("ready ")) {
            process.destroyForcibly();
            throw new IllegalStateException("member did not start: " + ready);
        }
        this.address = ready.substring("ready ".length());
    }

    /** Starts a member: {@code prefix} (may be empty) then java running {@link ScriptedMember} with {@code args}. */
    static MemberProcess start(List<String> prefix, List<String> args, Path log) throws IOException {
        List<String> command = new ArrayList<>(prefix);
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-Xmx256m");
        for (String argument : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (argument.startsWith("--add-")) {
                command.add(argument); // Hazelcast's access to JDK internals, as in this JVM
            }
        }
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(ScriptedMember.class.getName());
        command.addAll(args);
        Process process = new ProcessBuilder(command).redirectError(log.toFile()).start();
        return new MemberProcess(process, Duration.ofSeconds(90));
    }

    String address() {
        return address;
    }

    /** Sends a command and returns its answer line ({@code ok ...}, {@code error ...}). */
    String send(String command, Duration within) throws IOException {
        commands.write(command + "\n");
        commands.flush();
        return next(within);
    }

    private String next(Duration within) {
        try {
            String line = lines.poll(within.toMillis(), TimeUnit.MILLISECONDS);
            if (line == null) {
                throw new IllegalStateException("no answer from the member within " + within);
            }
            return line;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }

    /** {@code kill -9}: no goodbye, its connections just close. */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor(30, TimeUnit.SECONDS);
    }

    @Override
    public void close() {
        try {
            commands.write("quit\n");
            commands.flush();
        } catch (IOException e) {
            // already gone
        }
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                process.waitFor(10, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }
}
