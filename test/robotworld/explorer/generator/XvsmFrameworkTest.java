package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import robotworld.explorer.FrameworkGenerator;
import robotworld.testsupport.ProjectFiles;

/** Communication type xvsm: every viewpoint of both example worlds, with a control program compiled in. */
class XvsmFrameworkTest {

    static final Path CHAPTER5 = ProjectFiles.resolve("docs/examples/chapter5-world.xml");
    static final Path LAB = ProjectFiles.resolve("docs/examples/lab-world.xml");

    /** Listing 5.2, as a user writes it with the world-unique names. */
    static final String LISTING_5_2 = """
            final int LEFT = 1;
            final int RIGHT = 2;
            final long backOff = 500;
            final long evaluate = 3 * backOff * 2;
            final long turn = 2 * backOff;
            for (int round = 0; round < 1; round++) {
                MotorModule1.setMotor(LEFT, 0.25);
                MotorModule1.setMotor(RIGHT, 0.25);
                if (BumperModule1.getSingleBumper(6) || BumperModule1.getSingleBumper(4)) {
                    MotorModule1.setMotor(LEFT, -0.3);
                    MotorModule1.setMotor(RIGHT, -0.3);
                    Thread.sleep(backOff);
                    X10ApplianceModule1.on();
                    Thread.sleep(evaluate);
                    MotorModule1.setMotor(LEFT, 0.4);
                    MotorModule1.setMotor(RIGHT, -0.4);
                    Thread.sleep(turn);
                    X10ApplianceModule1.off();
                }
            }
            """;

    /** Every module of the lab world, by its world-unique name. */
    static final String LAB_PROGRAM = """
            ServoModule1.setServo(1, 90);
            ServoModule2.setServoQuiet(2, 45);
            MotorModule1.setMotor(1, 0.5);
            MotorModule2.setMotorQuiet(2, -0.5);
            X10LampModule1.on();
            X10LampModule1.dim(20);
            X10LampModule1.brighten(10);
            X10ApplianceModule1.off();
            """;

    @TempDir
    Path temp;

    static Stream<Arguments> viewpoints() {
        return Stream.of(
                Arguments.of(CHAPTER5, "CaterpillarRobot", LISTING_5_2),
                Arguments.of(CHAPTER5, "DimRoom", LISTING_5_2),
                Arguments.of(CHAPTER5, "external", LISTING_5_2),
                Arguments.of(LAB, "OEFAI_Labor", LAB_PROGRAM),
                Arguments.of(LAB, "MyRobot1", LAB_PROGRAM),
                Arguments.of(LAB, "MyRobot2", LAB_PROGRAM),
                Arguments.of(LAB, "external", LAB_PROGRAM));
    }

    /** Each project, with the control program in its main class, builds with its own build.xml and plain Ant. */
    @ParameterizedTest(name = "{1} of {0}")
    @MethodSource("viewpoints")
    void theSameControlProgramBuildsInEveryViewpointWithPlainAnt(Path world, String viewpoint, String program)
            throws Exception {
        GenerationResult result = new FrameworkGenerator().generate(world, viewpoint, null, temp.resolve("p"),
                false, GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        String mainSource = "src/" + result.mainClass().replace('.', '/') + ".java";
        project.insertControlLogic(mainSource, program);
        project.antCompile();
        assertTrue(java.nio.file.Files.isRegularFile(project.root().resolve("build/classes/"
                + result.mainClass().replace('.', '/') + ".class")));
    }

    @Test
    void viewpointOwnsItsModulesLocallyAndReachesTheRestRemotely() throws Exception {
        GenerationResult result = new FrameworkGenerator().generate(LAB, "MyRobot2", null, temp.resolve("p"),
                false, GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        String robot2 = project.read("src/MyWorld/MyRobot2.java");
        assertTrue(robot2.contains("ServoModule2 = runtime.own(new XVSMServoModuleLocal(runtime, NAME, "
                + "\"Servo-Controller\",\n                new robotworld.bus.ServoModuleProxy(bus, 1, "
                + "\"Servo-Controller\")));"), robot2);
        assertTrue(robot2.contains("public final MotorModule MotorModule1;"), "MyRobot1's motor, reached remotely");
        assertTrue(robot2.contains("robotworld.bus.RS485Bus bus = runtime.own(ParticipantMain.open(NAME, \"bus\", "
                + "\"tcp://robot2:4001\",\n                robotworld.bus.RS485Bus::new));"), robot2);
        String robot1 = project.read("src/MyWorld/MyRobot1.java");
        assertTrue(robot1.contains("MotorModule1 = runtime.own(new XVSMMotorModuleRemote(runtime, NAME, "
                + "\"Motor-Controller\"));"), robot1);
        String lab = project.read("src/MyWorld/OEFAI_Labor.java");
        assertTrue(lab.contains("X10LampModule1 = runtime.own(new XVSMX10LampModuleRemote("), lab);
        assertEquals("MyWorld.MyRobot2", result.mainClass());
    }

    /** A Host written as a URL, as the thesis writes hosts, names the host by its host part. */
    @Test
    void hostGivenAsUrlIsItsHostName() throws Exception {
        Path world = java.nio.file.Files.writeString(temp.resolve("url-host.xml"), java.nio.file.Files
                .readString(CHAPTER5).replace("<Host>robot-laptop</Host>", "<Host>http://robot-laptop:8080/robot</Host>")
                .replace("<Host>room-pc</Host>", "<Host>tcp://[::1]:5000</Host>"));
        GenerationResult result = new FrameworkGenerator().generate(world, "CaterpillarRobot", null, temp.resolve("p"),
                false, GenerationListener.SILENT);
        String robot = new GeneratedProject(result.destination()).read("src/chapter5/CaterpillarRobot.java");
        assertTrue(robot.contains("public static final String HOST = \"robot-laptop\";"), robot);
        result = new FrameworkGenerator().generate(world, "DimRoom", null, temp.resolve("q"), false,
                GenerationListener.SILENT);
        String room = new GeneratedProject(result.destination()).read("src/chapter5/DimRoom.java");
        assertTrue(room.contains("public static final String HOST = \"[::1]\";"), room);
    }

    /** A clustered space's servers, listed in the world, reach the program as one value its runtime fails over in. */
    @Test
    void severalSpaceServersGenerateAndBuild() throws Exception {
        Path world = java.nio.file.Files.writeString(temp.resolve("cluster.xml"), java.nio.file.Files
                .readString(CHAPTER5).replace("<SpaceURL>http://localhost:9876/space</SpaceURL>",
                        "<SpaceURL>http://pc-a:9876/space, http://pc-b:9876/space,http://[::1]:9876/space</SpaceURL>"));
        GenerationResult result = new FrameworkGenerator().generate(world, "DimRoom", null, temp.resolve("p"),
                false, GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        String room = project.read("src/chapter5/DimRoom.java");
        assertTrue(room.contains("public static final String SPACE_URL = "
                + "\"http://pc-a:9876/space, http://pc-b:9876/space,http://[::1]:9876/space\";"), room);
        assertEquals(3, robotworld.space.remote.SpaceUrls.parse(
                "http://pc-a:9876/space, http://pc-b:9876/space,http://[::1]:9876/space").size());
        project.antCompile();
    }

    @Test
    void environmentViewpointOpensItsCm11a() throws Exception {
        GenerationResult result = new FrameworkGenerator().generate(CHAPTER5, "DimRoom", null, temp.resolve("p"),
                false, GenerationListener.SILENT);
        String room = new GeneratedProject(result.destination()).read("src/chapter5/DimRoom.java");
        assertTrue(room.contains("runtime.own(ParticipantMain.open(NAME, \"x10\", \"/dev/ttyS0\",\n"
                + "                robotworld.x10.CM11aController::open));"), room);
        assertTrue(room.contains("new robotworld.x10.X10ApplianceModuleLocal(x10, 'A', 3)"), room);
        assertTrue(room.contains("public static final String SPACE_URL = \"http://localhost:9876/space\";"), room);
    }

    /**
     * Validation refuses bidirectional controls in any text; a world built in memory is not validated, so the
     * generator writes them out as text itself: none reaches a generated file.
     */
    @Test
    void bidiControlsNeverReachGeneratedSources() throws Exception {
        robotworld.description.RobotWorldDocument world = robotworld.description.DescriptionLoader.loadWorld(CHAPTER5);
        world.getRobotWorld().getRobotDescriptionArray(0).getModuleArray(1)
                .setDetails("bumper \u202E }; if (true) { \u2066 evil \u2069 \u200F");
        GenerationResult result = new FrameworkGenerator().generate(world, "CaterpillarRobot", null,
                temp.resolve("p"), false, GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        String robot = project.read("src/chapter5/CaterpillarRobot.java");
        assertTrue(robot.contains("bumper [U+202E] }; if (true) { [U+2066] evil [U+2069] [U+200F]"), robot);
        for (Path file : result.files()) {
            if (!file.toString().endsWith(".jar")) {
                assertTrue(java.nio.file.Files.readString(file).codePoints()
                        .noneMatch(c -> Character.getType(c) == Character.FORMAT), file + " has a formatting character");
            }
        }
        assertEquals("", project.compile(temp.resolve("classes")));
    }

    @Test
    void hostileFreeTextCannotBreakOutOfComments() throws Exception {
        String hostile = "x */ static { System.exit(1); } /* \\u000a class Evil {} \\u002a/";
        Path world = java.nio.file.Files.writeString(temp.resolve("hostile.xml"),
                java.nio.file.Files.readString(CHAPTER5).replace("front bumpers on inputs 4 and 6", hostile));
        GenerationResult result = new FrameworkGenerator().generate(world, "CaterpillarRobot", null,
                temp.resolve("p"), false, GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        String robot = project.read("src/chapter5/CaterpillarRobot.java");
        assertTrue(!robot.contains("*/ static") && !robot.contains("\\u000a"), robot);
        assertEquals("", project.compile(temp.resolve("classes")));
        // the program still has exactly its own classes: nothing was smuggled in
        try (var classes = java.nio.file.Files.walk(temp.resolve("classes"))) {
            assertEquals(java.util.List.of("CaterpillarRobot.class", "DimRoom.class"), classes
                    .filter(f -> f.toString().endsWith(".class")).map(f -> f.getFileName().toString()).sorted()
                    .toList());
        }
    }
}
