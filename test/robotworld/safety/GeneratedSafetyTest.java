package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.FrameworkGenerator;
import robotworld.explorer.generator.GeneratedProject;
import robotworld.explorer.generator.GenerationListener;
import robotworld.explorer.generator.GenerationResult;
import robotworld.testsupport.ProjectFiles;

/**
 * Generated projects carry the safety layer: a module's {@code <Safety>} reaches its program, a generated program
 * of either communication type that fails or is stopped leaves its motors at 0, and bad safety values are refused
 * with their position.
 */
class GeneratedSafetyTest {

    private static final Path LAB = ProjectFiles.resolve("docs/examples/lab-world.xml");

    @TempDir
    Path temp;

    @Test
    void theDescriptionsSafetyValuesReachTheGeneratedPrograms() throws Exception {
        FrameworkGenerator generator = new FrameworkGenerator();
        GenerationResult robot = generator.generate(LAB, "MyRobot2", null, temp.resolve("robot"), false,
                GenerationListener.SILENT);
        GenerationResult lab = generator.generate(LAB, "OEFAI_Labor", null, temp.resolve("lab"), false,
                GenerationListener.SILENT);
        String robotSource = new GeneratedProject(robot.destination()).read("src/MyWorld/MyRobot2.java");
        assertTrue(robotSource.contains("runtime.safety().describe(NAME, \"Motor-Controller\", "
                + "new robotworld.safety.ModuleSafety(300, 250, null));"), robotSource);
        assertTrue(robotSource.contains("runtime.failed(failure);"), robotSource);
        String labSource = new GeneratedProject(lab.destination()).read("src/MyWorld/OEFAI_Labor.java");
        assertTrue(labSource.contains("runtime.safety().describe(NAME, \"Fan\", "
                + "new robotworld.safety.ModuleSafety(null, null, \"off\"));"), labSource);
        assertEquals("", new GeneratedProject(robot.destination()).compile(temp.resolve("c1")));
        assertEquals("", new GeneratedProject(lab.destination()).compile(temp.resolve("c2")));
    }

    @Test
    void aGeneratedProgramOfTypeXvsmThatFailsStopsItsMotors() throws Exception {
        try (SafetyRig rig = SafetyRig.start()) {
            Path world = rig.writeWorld(temp.resolve("world.xml"));
            GenerationResult result = new FrameworkGenerator().generate(world, SafetyRig.ROBOT, "gen",
                    temp.resolve("robot"), false, GenerationListener.SILENT);
            GeneratedProject project = new GeneratedProject(result.destination());
            project.insertControlLogic("src/gen/SafetyBot.java", """
                    MotorModule1.setMotor(1, 0.45);
                    MotorModule1.setMotor(2, 0.45);
                    throw new IllegalStateException("the control program failed on purpose");
                    """);
            String output = run(project, "gen.SafetyBot", List.of("-Drwe.host=robot-pc"), 1);
            assertTrue(output.contains("SafetyBot/Motor stopped at"), output);
            assertTrue(output.contains("(program-failed: the program failed: java.lang.IllegalStateException"), output);
            assertTrue(rig.motorsStopped(), output);
        }
    }

    @Test
    void aGeneratedProgramOfTypeNoneThatFailsStopsItsMotors() throws Exception {
        try (SafetyRig rig = SafetyRig.start()) {
            Path world = Files.writeString(temp.resolve("none.xml"), Files.readString(
                    rig.writeWorld(temp.resolve("world.xml"))).replace("<CommunicationType>xvsm", "<CommunicationType>none"));
            GenerationResult result = new FrameworkGenerator().generate(world, SafetyRig.ROBOT, "gen",
                    temp.resolve("robot"), false, GenerationListener.SILENT);
            GeneratedProject project = new GeneratedProject(result.destination());
            String source = project.read("src/gen/SafetyBot.java");
            assertTrue(source.contains("MotorModule1 = safety.guard(NAME, \"Motor\", new robotworld.bus."
                    + "MotorModuleProxy(bus, 1, \"Motor\"));"), source);
            project.insertControlLogic("src/gen/SafetyBot.java", """
                    MotorModule1.setMotor(1, 0.45);
                    throw new IllegalStateException("the control program failed on purpose");
                    """);
            String output = run(project, "gen.SafetyBot", List.of(), 1);
            assertTrue(output.contains("(program-failed: the program failed: java.lang.IllegalStateException"), output);
            assertTrue(rig.motorsStopped(), output);
            assertEquals(SafetySettings.DEFAULT_MOTOR_WATCHDOG_MILLIS, rig.robot.module(1).watchdogMillis(),
                    "armed by the program");
        }
    }

    @Test
    void safetyValuesOutsideTheirRangesAreRefusedWithTheirPosition() throws Exception {
        String world = Files.readString(LAB).replace("<Watchdog>250</Watchdog>", "<Watchdog>5</Watchdog>")
                .replace("<SafeState>off</SafeState>", "<SafeState>dim</SafeState>")
                .replace("<CommandTimeout>300</CommandTimeout>", "<CommandTimeout>10</CommandTimeout>");
        Path file = Files.writeString(temp.resolve("bad-safety.xml"), world);
        DescriptionException refused = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(file, DescriptionSchemas.configured()));
        List<String> errors = refused.errors().stream().map(DescriptionError::toString).toList();
        assertTrue(errors.stream().anyMatch(e -> e.matches(".*bad-safety\\.xml:\\d+:\\d+: .*dim.*")), errors.toString());
        assertTrue(errors.stream().anyMatch(e -> e.contains(":") && e.contains("5")), errors.toString());
        assertTrue(errors.stream().anyMatch(e -> e.contains("10")), errors.toString());
    }

    /** Runs a generated main class against the rig in a JVM of its own; returns its output. */
    private String run(GeneratedProject project, String mainClass, List<String> properties, int expectedExit)
            throws Exception {
        Path classes = temp.resolve("classes-" + mainClass);
        assertEquals("", project.compile(classes));
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-XX:TieredStopAtLevel=1"));
        command.addAll(properties);
        StringBuilder classPath = new StringBuilder(classes.toString());
        for (Path jar : project.libraries()) {
            classPath.append(File.pathSeparator).append(jar);
        }
        command.addAll(List.of("-cp", classPath.toString(), mainClass));
        Path log = temp.resolve(mainClass + ".log");
        Process process = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        if (!process.waitFor(Duration.ofSeconds(60).toMillis(), TimeUnit.MILLISECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("did not end: " + Files.readString(log));
        }
        String output = Files.readString(log);
        assertEquals(expectedExit, process.exitValue(), output);
        return output;
    }
}
