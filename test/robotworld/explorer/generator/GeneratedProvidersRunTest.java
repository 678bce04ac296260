package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.core.BumperModule;
import robotworld.core.MotorModule;
import robotworld.core.X10ApplianceModule;
import robotworld.explorer.FrameworkGenerator;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.sim.robot.SimMotorModule;
import robotworld.sim.robot.SimServoModule;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.ProjectFiles;
import robotworld.x10.X10Address;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMServoModuleRemote;
import robotworld.xvsm.XVSMX10LampModuleRemote;
import robotworld.xvsm.XVSMX10ApplianceModuleRemote;

/**
 * The generated chapter-5 projects, built with their own build.xml by plain Ant, run unchanged as providers in
 * their own JVMs against a space server and the simulators; a third program drives their modules remotely.
 */
class GeneratedProvidersRunTest {

    private static final Path CHAPTER5 = ProjectFiles.resolve("docs/examples/chapter5-world.xml");
    private static final Path LAB = ProjectFiles.resolve("docs/examples/lab-world.xml");
    private static final Duration START_TIMEOUT = Duration.ofSeconds(60);

    @TempDir
    Path temp;

    private final List<Process> providers = new ArrayList<>();

    @AfterEach
    void stopProviders() throws InterruptedException {
        for (Process provider : providers) {
            provider.destroy();
            if (!provider.waitFor(10, TimeUnit.SECONDS)) {
                provider.destroyForcibly();
            }
        }
    }

    @Test
    void robotAndEnvironmentProvidersServeTheirHardwareToAnExternalProgram() throws Exception {
        try (SpaceServer space = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
             SimulatedCm11a cm11a = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A3=appliance");
             SimulatedRobot robot = SimulatedRobot.load(ProjectFiles.resolve("docs/examples/simulated-robot.sim"))) {
            String x10Port = cm11a.listen(0);
            String busPort = robot.serve("tcp://127.0.0.1:0");
            String spaceUrl = space.uri().toString();

            FrameworkGenerator generator = new FrameworkGenerator();
            Path room = buildWithAnt(generator.generate(CHAPTER5, "DimRoom", null, temp.resolve("room"), false,
                    GenerationListener.SILENT));
            Path laptop = buildWithAnt(generator.generate(CHAPTER5, "CaterpillarRobot", null, temp.resolve("robot"),
                    false, GenerationListener.SILENT));
            start(room, "chapter5.DimRoom", "-Drwe.space.url=" + spaceUrl, "-Drwe.port.DimRoom.x10=" + x10Port);
            start(laptop, "chapter5.CaterpillarRobot", "-Drwe.space.url=" + spaceUrl,
                    "-Drwe.port.CaterpillarRobot.bus=" + busPort);

            try (XVSMRuntime external = XVSMRuntime.connect(spaceUrl, "monitor-pc")) {
                X10ApplianceModule lamp = external.own(new XVSMX10ApplianceModuleRemote(external, "DimRoom", "Lamp"));
                MotorModule motor = external.own(new XVSMMotorModuleRemote(external, "CaterpillarRobot",
                        "Motor-Controller"));
                BumperModule bumper = external.own(new XVSMBumperModuleRemote(external, "CaterpillarRobot",
                        "Bumper-Sensor"));
                // the providers are still starting: the first calls wait in the space until they serve
                ((XVSMX10ApplianceModuleRemote) lamp).setCallTimeout(START_TIMEOUT);
                ((XVSMMotorModuleRemote) motor).setCallTimeout(START_TIMEOUT);
                ((XVSMBumperModuleRemote) bumper).setCallTimeout(START_TIMEOUT);

                lamp.on();
                assertTrue(cm11a.appliance(X10Address.of('A', 3)).isOn(), "X10 frames reached the CM11A");
                lamp.off();
                assertFalse(cm11a.appliance(X10Address.of('A', 3)).isOn());

                motor.setMotor(1, 0.25);
                assertEquals(250, ((SimMotorModule) robot.module(1)).setSpeed(1), "per-mille on the bus");
                motor.setMotor(1, 0);
                assertEquals(0, bumper.getAllBumper() & ~0xff, "an 8-bit contact mask");
            }
            for (Process provider : providers) {
                assertTrue(provider.isAlive(), "a provider serves until it is stopped");
            }
        }
    }

    @Test
    void labProvidersServeTheirServosMotorsAndLamps() throws Exception {
        Path labRobot = ProjectFiles.resolve("test/robotworld/explorer/generator/lab-robot.sim");
        try (SpaceServer space = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
             SimulatedCm11a cm11a = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "B1=lamp,B2=appliance");
             SimulatedRobot robot1 = SimulatedRobot.load(labRobot);
             SimulatedRobot robot2 = SimulatedRobot.load(labRobot)) {
            String spaceUrl = space.uri().toString();
            FrameworkGenerator generator = new FrameworkGenerator();
            Path lab = buildWithAnt(generator.generate(LAB, "OEFAI_Labor", null, temp.resolve("lab"), false,
                    GenerationListener.SILENT));
            Path one = buildWithAnt(generator.generate(LAB, "MyRobot1", null, temp.resolve("one"), false,
                    GenerationListener.SILENT));
            Path two = buildWithAnt(generator.generate(LAB, "MyRobot2", null, temp.resolve("two"), false,
                    GenerationListener.SILENT));
            start(lab, "MyWorld.OEFAI_Labor", "-Drwe.space.url=" + spaceUrl,
                    "-Drwe.port.OEFAI_Labor.x10=" + cm11a.listen(0));
            start(one, "MyWorld.MyRobot1", "-Drwe.space.url=" + spaceUrl,
                    "-Drwe.port.MyRobot1.bus=" + robot1.serve("tcp://127.0.0.1:0"));
            start(two, "MyWorld.MyRobot2", "-Drwe.space.url=" + spaceUrl,
                    "-Drwe.port.MyRobot2.bus=" + robot2.serve("tcp://127.0.0.1:0"));

            try (XVSMRuntime external = XVSMRuntime.connect(spaceUrl, "monitor-pc")) {
                XVSMServoModuleRemote arm = external.own(new XVSMServoModuleRemote(external, "MyRobot1",
                        "Servo-Controller"));
                XVSMMotorModuleRemote drive = external.own(new XVSMMotorModuleRemote(external, "MyRobot2",
                        "Motor-Controller"));
                XVSMX10LampModuleRemote lamp = external.own(new XVSMX10LampModuleRemote(external, "OEFAI_Labor",
                        "Ceiling-Lamp"));
                arm.setCallTimeout(START_TIMEOUT);
                drive.setCallTimeout(START_TIMEOUT);
                lamp.setCallTimeout(START_TIMEOUT);

                arm.setServo(1, 90); // returns once the servo reports it arrived
                assertEquals(90.0, ((SimServoModule) robot1.module(1)).angle(1), 0.5);
                drive.setMotor(2, -0.5);
                assertEquals(-500, ((SimMotorModule) robot2.module(2)).setSpeed(2));
                lamp.on();
                assertTrue(cm11a.lamp(X10Address.of('B', 1)).isOn());
            }
        }
    }

    /** Runs the project's own build.xml with plain Ant (compile), as a user would. */
    private static Path buildWithAnt(GenerationResult result) throws IOException, InterruptedException {
        new GeneratedProject(result.destination()).antCompile();
        return result.destination();
    }

    private void start(Path project, String mainClass, String... properties) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString()));
        command.addAll(List.of(properties));
        command.addAll(List.of("-cp", project.resolve("build/classes") + File.pathSeparator
                + project.resolve("lib") + File.separator + "*", mainClass));
        providers.add(new ProcessBuilder(command).directory(project.toFile()).redirectErrorStream(true)
                .redirectOutput(project.resolve("provider.log").toFile()).start());
    }
}
