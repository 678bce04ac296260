package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BusTimeoutException;
import robotworld.bus.BusTiming;
import robotworld.bus.IRDistanceModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.testsupport.ProjectFiles;
import robotworld.x10.CM11aConfig;
import robotworld.x10.CM11aController;
import robotworld.x10.X10Event;

/**
 * {@code rwe simulate cm11a --control stdin} and {@code rwe simulate robot --control tcp://...} as a person runs
 * them: the real command in a JVM of its own (the built jar, as {@code ./rwe} starts it), driven through its control
 * channel while a client talks to the simulated device.
 */
class SimulatorControlCommandTest {

    /** Generous: the child JVM starts on a busy machine. */
    private static final Duration START = Duration.ofSeconds(60);

    @TempDir
    Path temp;

    /** The command in a JVM of its own; its standard output is read line by line. */
    private static final class Child implements AutoCloseable {
        private final Process process;
        private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        private final List<String> seen = new ArrayList<>();

        Child(Path temp, String... args) throws IOException {
            Path jar = Path.of(System.getProperty("rwe.build.dir", "build"), "dist", "robotworldexplorer.jar");
            List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                    .toString(), "-Drwe.home=" + ProjectFiles.root(), "-jar", jar.toAbsolutePath().toString()));
            command.addAll(List.of(args));
            process = new ProcessBuilder(command).directory(ProjectFiles.root().toFile())
                    .redirectError(temp.resolve("err-" + System.nanoTime()).toFile()).start();
            Thread reader = new Thread(() -> {
                try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(),
                        StandardCharsets.UTF_8))) {
                    for (String line = in.readLine(); line != null; line = in.readLine()) {
                        lines.add(line);
                    }
                } catch (IOException e) {
                    // the process ended
                }
            }, "rwe-stdout");
            reader.setDaemon(true);
            reader.start();
        }

        /** The first group of the first line (from here on) that matches {@code pattern}. */
        String await(String pattern, Duration limit) throws InterruptedException {
            Pattern wanted = Pattern.compile(pattern);
            long deadline = System.nanoTime() + limit.toNanos();
            while (true) {
                String line = lines.poll(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                if (line == null) {
                    throw new AssertionError("no line like '" + pattern + "' within " + limit.toSeconds()
                            + " s (alive: " + process.isAlive() + "); its output so far:\n" + String.join("\n", seen));
                }
                seen.add(line);
                Matcher matcher = wanted.matcher(line);
                if (matcher.find()) {
                    return matcher.groupCount() > 0 ? matcher.group(1) : line;
                }
            }
        }

        void type(String line) throws IOException {
            OutputStream in = process.getOutputStream();
            in.write((line + "\n").getBytes(StandardCharsets.UTF_8));
            in.flush();
        }

        @Override
        public void close() {
            process.destroy(); // SIGTERM, as Ctrl-C would
            try {
                if (!process.waitFor(30, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                }
            } catch (InterruptedException e) {
                process.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }

    @Test
    void aRemoteControlTypedIntoTheCm11aSimulatorReachesTheControllersListener() throws Exception {
        try (Child sim = new Child(temp, "simulate", "cm11a", "--port", "tcp://127.0.0.1:0", "--devices",
                "A1=lamp,A5=appliance", "--timing", "fast", "--control", "stdin")) {
            String port = sim.await("simulated CM11A on (tcp://127\\.0\\.0\\.1:\\d+)", START);
            sim.await("control channel on standard input", START);
            BlockingQueue<X10Event> events = new LinkedBlockingQueue<>();
            try (CM11aController controller = CM11aController.open(port, CM11aConfig.defaults().forFastSimulator())) {
                controller.addListener(events::add);
                sim.type("remote A5 on");
                sim.await("^ok A5 On$", START);
                assertEquals("A5 On", String.valueOf(events.poll(30, TimeUnit.SECONDS)),
                        "the interface uploads what the remote sent");
                sim.type("house A all-lights-off");
                sim.await("^ok A All Lights Off$", START);
                String allOff = String.valueOf(events.poll(30, TimeUnit.SECONDS));
                assertTrue(allOff.startsWith("A") && allOff.endsWith("All Lights Off"), allOff);
                sim.type("remote Z9 on");
                assertTrue(sim.await("^(error .*)$", START).startsWith("error 'Z9' is not an X10 address"));
            }
        }
    }

    @Test
    void theRobotSimulatorIsMovedAndItsModuleFailedThroughItsTcpControlChannel() throws Exception {
        String config = ProjectFiles.resolve("docs/examples/simulated-robot.sim").toString();
        try (Child sim = new Child(temp, "simulate", "robot", "--config", config, "--port", "tcp://127.0.0.1:0",
                "--timing", "fast", "--quiet", "--control", "tcp://127.0.0.1:0")) {
            String port = sim.await("serving the bus on (tcp://127\\.0\\.0\\.1:\\d+)", START);
            String control = sim.await("control channel on (tcp://127\\.0\\.0\\.1:\\d+)", START);
            URI where = URI.create(control);
            try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(115_200), BusTiming.defaults()
                    .withResponseTimeout(Duration.ofMillis(500)));
                    Socket socket = new Socket(where.getHost(), where.getPort())) {
                socket.setSoTimeout(30_000);
                PrintWriter out = new PrintWriter(socket.getOutputStream(), true, StandardCharsets.UTF_8);
                BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(),
                        StandardCharsets.UTF_8));
                IRDistanceModuleProxy ir = new IRDistanceModuleProxy(bus, 4, "IR");
                assertEquals(800, ir.getSingleSensor(1), "nothing within range ahead of the start");

                out.println("place 1500 1000 0"); // 500 mm before the crate at x = 2000, facing it
                assertEquals("ok 1500.0 1000.0 0.0", in.readLine());
                assertEquals(350, ir.getSingleSensor(1), 2, "the crate 350 mm ahead of the body");

                out.println("fail 2 silent");
                assertEquals("ok address 2: silent", in.readLine());
                assertThrows(BusTimeoutException.class, () -> bus.identify(2));
                out.println("fail 2 none");
                assertEquals("ok address 2: none", in.readLine());
                assertEquals("15B63B2", bus.identify(2).productCode(), "answering again");
            }
        }
    }
}
