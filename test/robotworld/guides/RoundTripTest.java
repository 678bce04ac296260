package robotworld.guides;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.explorer.cli.Rwe;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.sim.robot.SimMotorModule;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.ProjectFiles;
import robotworld.x10.X10Address;

/**
 * From an explored robot to a running experiment with no XML written by hand: rwe explore, rwe assemble (the lamp
 * from --x10), rwe generate for both viewpoints, and each project run with {@code ant run} as printed by rwe
 * generate: the robot's program as generated, serving its modules, and the environment's with a control program
 * that drives the robot and switches its own lamp. The simulators show that the motors and the lamp did what the
 * program said, and the control program ends its process by itself. (The README's step by step, run by
 * ReadmeTest, does the same with the program on the robot's computer.)
 */
class RoundTripTest {

    /** Drives the robot a little, switches the lamp, and stops the robot; the same text in either viewpoint. */
    private static final String PROGRAM = """
            MotorModule1.setMotor(1, 0.3);
            MotorModule1.setMotor(2, -0.3);
            X10LampModule1.on();
            System.out.println("round trip: distance ahead " + IRDistanceModule1.getSingleSensor(1) + " mm");
            Thread.sleep(300);
            MotorModule1.setMotor(1, 0);
            MotorModule1.setMotor(2, 0);
            """;

    @TempDir
    Path folder;

    @Test
    void exploreAssembleGenerateAndRunBothViewpoints() throws Exception {
        String antBin = Walkthrough.ant();
        try (SpaceServer space = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
             SimulatedCm11a cm11a = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp");
             SimulatedRobot robot = SimulatedRobot.load(ProjectFiles.resolve("docs/examples/simulated-robot.sim"))) {
            java.util.concurrent.atomic.AtomicInteger lampOn = new java.util.concurrent.atomic.AtomicInteger();
            cm11a.onPowerLine(frame -> {
                if (frame.equals("A On")) {
                    lampOn.incrementAndGet();
                }
            });
            String busPort = robot.serve("tcp://127.0.0.1:0");
            String x10Port = cm11a.listen(0);
            Path robotFile = folder.resolve("Rover.xml");
            Path world = folder.resolve("Trip.xml");
            rwe("explore", "--port", busPort, "--name", "Rover", "--out", robotFile.toString());
            rwe("assemble", "--robot", robotFile.toString(), "--x10", "A1=lamp:Lamp", "--environment-name", "Lab",
                    "--cm11a-port", x10Port, "--space", space.uri().toString(), "--name", "Trip",
                    "--out", world.toString());

            // the control program on the environment's computer, the robot serving its modules (the other way round,
            // program on the robot and the lamp served by the environment, is the README's step by step)
            String providerRun = generate(world, "Rover", "rover-provider", null);
            String controllerRun = generate(world, "Lab", "lab-control", PROGRAM);
            double headingBefore;
            try (Running rover = Running.start(providerRun, folder, antBin)) {
                rover.awaitServing();
                headingBefore = robot.pose().heading();
                String output = runToEnd(controllerRun, antBin);
                assertTrue(output.contains("round trip: distance ahead "), output);
            }
            assertEquals(1, lampOn.get(), "the environment's program switched its own lamp");
            assertTrue(Math.abs(robot.pose().heading() - headingBefore) > 0.01, "the robot turned: " + robot.pose());
            assertEquals(0, ((SimMotorModule) robot.module(1)).setSpeed(2), "and stopped the robot through the space");
        }
    }

    /** rwe generate, the program put between the markers; returns the run command rwe generate printed. */
    private String generate(Path world, String viewpoint, String project, String program) throws Exception {
        String output = rwe("generate", world.toString(), "--viewpoint", viewpoint, "--out",
                folder.resolve(project).toString());
        String command = output.lines().filter(line -> line.startsWith("  cd ")).findFirst().orElseThrow().strip();
        assertTrue(command.contains("ant run -Drwe.space.url="), command);
        if (program != null) {
            Path main;
            try (var files = Files.walk(folder.resolve(project).resolve("src"))) {
                main = files.filter(f -> f.getFileName().toString().equals(viewpoint + ".java")).findFirst()
                        .orElseThrow();
            }
            String source = Files.readString(main);
            int begin = source.indexOf('\n', source.indexOf(Walkthrough.CONTROL_BEGIN)) + 1;
            int end = source.lastIndexOf('\n', source.indexOf(Walkthrough.CONTROL_END)) + 1;
            Files.writeString(main, source.substring(0, begin) + program + source.substring(end));
        }
        return command;
    }

    private static String rwe(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
        assertEquals(0, code, String.join(" ", args) + ":\n" + err);
        return out.toString();
    }

    private String runToEnd(String command, String antBin) throws Exception {
        Path log = Files.createTempFile(folder, "run", ".log");
        Process process = Running.shell(command, folder, antBin, log);
        assertTrue(process.waitFor(180, TimeUnit.SECONDS), "the control program ends by itself:\n"
                + Walkthrough.tail(log));
        String output = Files.readString(log, StandardCharsets.UTF_8);
        assertEquals(0, process.exitValue(), output);
        return output;
    }

    /** A program started with its printed run command, running beside the test. */
    private static final class Running implements AutoCloseable {
        private final Process process;
        private final Path log;

        private Running(Process process, Path log) {
            this.process = process;
            this.log = log;
        }

        static Running start(String command, Path folder, String antBin) throws Exception {
            Path log = Files.createTempFile(folder, "provider", ".log");
            return new Running(shell(command, folder, antBin, log), log);
        }

        static Process shell(String command, Path folder, String antBin, Path log) throws Exception {
            ProcessBuilder builder = new ProcessBuilder("bash", "-c", command).directory(folder.toFile())
                    .redirectErrorStream(true).redirectOutput(log.toFile());
            List<String> path = new ArrayList<>(List.of(antBin, Path.of(System.getProperty("java.home"), "bin")
                    .toString(), builder.environment().getOrDefault("PATH", "/usr/bin:/bin")));
            builder.environment().put("PATH", String.join(":", path));
            Walkthrough.relaxTimings(builder.environment());
            builder.environment().put("JAVA_HOME", System.getProperty("java.home"));
            return builder.start();
        }

        void awaitServing() throws Exception {
            long deadline = System.nanoTime() + Duration.ofSeconds(180).toNanos();
            while (!Files.readString(log, StandardCharsets.UTF_8).contains("serving")) {
                assertTrue(process.isAlive(), "the provider ended:\n" + Walkthrough.tail(log));
                assertTrue(System.nanoTime() < deadline, "the provider does not serve:\n" + Walkthrough.tail(log));
                Thread.sleep(100);
            }
        }

        boolean isAlive() {
            return process.isAlive();
        }

        @Override
        public void close() {
            process.descendants().forEach(ProcessHandle::destroy);
            process.destroy();
            try {
                if (!process.waitFor(10, TimeUnit.SECONDS)) {
                    process.descendants().forEach(ProcessHandle::destroyForcibly);
                    process.destroyForcibly();
                }
            } catch (InterruptedException e) {
                process.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }
}
