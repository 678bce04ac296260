package robotworld.guides;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.JSerialCommLink;
import robotworld.bus.SerialSettings;
import robotworld.bus.SocatPty;
import robotworld.explorer.FrameworkGenerator;
import robotworld.explorer.cli.Rwe;
import robotworld.explorer.generator.GeneratedProject;
import robotworld.explorer.generator.GenerationListener;
import robotworld.explorer.generator.GenerationResult;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.ProjectFiles;
import robotworld.testsupport.TestPeers;

/**
 * Every operational failure a user meets, caused for real, in a generated program (its own JVM, as {@code ant run}
 * starts it) and in the rwe verbs: the exit code is not 0, standard error has at most three lines, none of them a
 * stack frame, and they name the fix (the property, option or command). With {@code -Drwe.debug=true} the trace is
 * there.
 */
class FailureReportsTest {

    private static final Path CHAPTER5 = ProjectFiles.resolve("docs/examples/chapter5-world.xml");

    @TempDir
    static Path folder;

    private static Path robot;
    private static Path room;
    private static Path external;
    private static SpaceServer space;
    private static Silent silent;

    /** The chapter-5 projects, each with a control program that uses a module, compiled as ant compile would. */
    @BeforeAll
    static void generate() throws Exception {
        FrameworkGenerator generator = new FrameworkGenerator();
        robot = project(generator, "CaterpillarRobot", "MotorModule1.setMotor(1, 0.2);\nMotorModule1.setMotor(1, 0);");
        room = project(generator, "DimRoom", "X10ApplianceModule1.on();");
        external = project(generator, "external", "X10ApplianceModule1.on();");
        space = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
        silent = new Silent();
    }

    @AfterAll
    static void stop() throws IOException {
        if (silent != null) {
            silent.close();
        }
        if (space != null) {
            space.stop();
        }
    }

    private static Path project(FrameworkGenerator generator, String viewpoint, String program) throws Exception {
        GenerationResult result = generator.generate(CHAPTER5, viewpoint, null, folder.resolve(viewpoint), false,
                GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        project.insertControlLogic("src/" + result.mainClass().replace('.', '/') + ".java", program);
        assertEquals("", project.compile(result.destination().resolve("build/classes")));
        return result.destination();
    }

    // ----- generated programs -----

    @Test
    void aMissingSerialPortNamesThePortProperty() throws Exception {
        Run run = program(robot, "chapter5.CaterpillarRobot", "-Drwe.space.url=" + space.uri(),
                "-Drwe.port.CaterpillarRobot.bus=/dev/ttyRWE-absent0");
        run.assertReport("there is no serial port /dev/ttyRWE-absent0", "-Drwe.port.CaterpillarRobot.bus=PORT");
    }

    @Test
    void aBusySerialPortSaysSo() throws Exception {
        TestPeers.requireCommand("socat", "socat");
        try (SocatPty pty = SocatPty.start()) {
            JSerialCommLink holder = new JSerialCommLink(pty.a().toString(), SerialSettings.eightNoneOne(115200));
            holder.open();
            try {
                Run run = program(room, "chapter5.DimRoom", "-Drwe.space.url=" + space.uri(),
                        "-Drwe.port.DimRoom.x10=" + pty.a());
                run.assertReport("is in use by", "-Drwe.port.DimRoom.x10=PORT");
            } finally {
                holder.close();
            }
        }
    }

    @Test
    void aSimulatorThatIsNotRunningIsNamedWithItsCommand() throws Exception {
        Run run = program(robot, "chapter5.CaterpillarRobot", "-Drwe.space.url=" + space.uri(),
                "-Drwe.port.CaterpillarRobot.bus=tcp://127.0.0.1:" + closedPort());
        run.assertReport("nothing answers at tcp://127.0.0.1:", "rwe simulate robot");
        assertTrue(run.stderr().contains("-Drwe.port.CaterpillarRobot.bus=PORT"), run.stderr());
    }

    @Test
    void aSilentRobotBusNamesWhatToCheck() throws Exception {
        Run run = program(robot, "chapter5.CaterpillarRobot", "-Drwe.space.url=" + space.uri(),
                "-Drwe.port.CaterpillarRobot.bus=tcp://127.0.0.1:" + silent.port());
        run.assertReport("no reply", "-Drwe.port.CaterpillarRobot.bus=PORT");
    }

    @Test
    void aSilentCm11aNamesWhatToCheck() throws Exception {
        Run run = program(room, "chapter5.DimRoom", "-Drwe.space.url=" + space.uri(),
                "-Drwe.port.DimRoom.x10=tcp://127.0.0.1:" + silent.port());
        run.assertReport("CM11A on tcp://127.0.0.1:", "-Drwe.port.DimRoom.x10=PORT");
    }

    @Test
    void anUnreachableSpaceNamesRweSpaceAndTheProperty() throws Exception {
        Run run = program(external, "chapter5.Chapter5WorldExternal",
                "-Drwe.space.url=http://127.0.0.1:" + closedPort() + "/space");
        run.assertReport("cannot reach the space", "rwe space --port");
        assertTrue(run.stderr().contains("-Drwe.space.url="), run.stderr());
    }

    @Test
    void aRefusedTokenNamesTheTokenFile() throws Exception {
        Path token = Files.writeString(folder.resolve("token"), "s3cret-token-for-the-test");
        try (SpaceServer guarded = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200)
                .token("s3cret-token-for-the-test"))) {
            program(external, "chapter5.Chapter5WorldExternal", "-Drwe.space.url=" + guarded.uri())
                    .assertReport("needs an access token", "-Drwe.space.tokenFile=FILE");
            Path wrong = Files.writeString(folder.resolve("wrong-token"), "not-the-token");
            program(external, "chapter5.Chapter5WorldExternal", "-Drwe.space.url=" + guarded.uri(),
                    "-Drwe.space.tokenFile=" + wrong).assertReport("refused the access token", "--token-file");
            assertTrue(Files.exists(token));
        }
    }

    @Test
    void aModuleWhoseProgramIsNotRunningNamesThatProgram() throws Exception {
        Run run = program(external, "chapter5.Chapter5WorldExternal", "-Drwe.space.url=" + space.uri(),
                "-Drwe.call.timeout.ms=1500");
        run.assertReport("no answer from DimRoom's Lamp within 1500 ms", "Start DimRoom's program");
    }

    @Test
    void theTraceComesWithDebugOnly() throws Exception {
        Run run = program(robot, "chapter5.CaterpillarRobot", "-Drwe.space.url=" + space.uri(),
                "-Drwe.port.CaterpillarRobot.bus=tcp://127.0.0.1:" + closedPort(), "-Drwe.debug=true");
        assertNotEquals(0, run.exit());
        assertTrue(run.stderr().contains("\tat robotworld."), run.stderr());
    }

    /** As the user runs it: ant run, whose output has Ant's own lines too, but no stack frame. */
    @Test
    void antRunShowsTheReportWithoutFrames() throws Exception {
        String antBin = Walkthrough.ant();
        ProcessBuilder builder = new ProcessBuilder(Path.of(antBin, "ant").toString(), "run",
                "-Drwe.space.url=" + space.uri(), "-Drwe.port.CaterpillarRobot.bus=/dev/ttyRWE-absent0")
                .directory(robot.toFile()).redirectErrorStream(true);
        builder.environment().put("JAVA_HOME", System.getProperty("java.home"));
        Path log = folder.resolve("ant-run.log");
        Process ant = builder.redirectOutput(log.toFile()).start();
        assertTrue(ant.waitFor(180, TimeUnit.SECONDS));
        String output = Files.readString(log);
        assertNotEquals(0, ant.exitValue(), output);
        assertTrue(output.contains("there is no serial port /dev/ttyRWE-absent0"), output);
        assertTrue(output.contains("-Drwe.port.CaterpillarRobot.bus=PORT"), output);
        assertTrue(output.lines().noneMatch(line -> line.replace("[java]", "").strip().startsWith("at ")), output);
    }

    // ----- rwe verbs -----

    @Test
    void exploreOnAMissingOrDeadPortNamesTheOption() {
        Verb missing = rwe("explore", "--port", "/dev/ttyRWE-absent0", "--name", "R", "--out",
                folder.resolve("r.xml").toString());
        missing.assertReport("there is no serial port /dev/ttyRWE-absent0", "--port PORT");
        Verb refused = rwe("explore", "--port", "tcp://127.0.0.1:" + closedPort(), "--name", "R", "--out",
                folder.resolve("r.xml").toString());
        refused.assertReport("nothing answers at", "rwe simulate robot");
    }

    @Test
    void monitorWithoutItsSpaceOrTokenNamesTheFix() throws Exception {
        rwe("monitor", "--console", "--for", "1", "--space", "http://127.0.0.1:" + closedPort() + "/space",
                CHAPTER5.toString()).assertReport("cannot reach the space", "--space URL");
        try (SpaceServer guarded = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200)
                .token("s3cret-token-for-the-test"))) {
            rwe("monitor", "--console", "--for", "1", "--space", guarded.uri().toString(), CHAPTER5.toString())
                    .assertReport("needs an access token", "RWE_SPACE_TOKEN_FILE");
        }
    }

    @Test
    void exploringASilentBusNamesWhatToCheck() {
        rwe("explore", "--port", "tcp://127.0.0.1:" + silent.port(), "--name", "R", "--from", "1", "--to", "3",
                "--out", folder.resolve("silent.xml").toString()).assertReport("no module answered", "--baud auto");
    }

    @Test
    void verbsShowTheTraceWithDebugOnly() {
        Verb quiet = rwe("explore", "--port", "tcp://127.0.0.1:" + closedPort(), "--name", "R", "--out",
                folder.resolve("q.xml").toString());
        assertTrue(!quiet.stderr().contains("\tat "), quiet.stderr());
        System.setProperty("rwe.debug", "true");
        try {
            Verb loud = rwe("explore", "--port", "tcp://127.0.0.1:" + closedPort(), "--name", "R", "--out",
                    folder.resolve("q.xml").toString());
            assertTrue(loud.stderr().contains("\tat robotworld."), loud.stderr());
        } finally {
            System.clearProperty("rwe.debug");
        }
    }

    @Test
    void serversOnABusyPortNameTheOption() throws Exception {
        try (ServerSocket busy = new ServerSocket(0)) {
            String port = Integer.toString(busy.getLocalPort());
            rwe("space", "--port", port).assertReport("already in use", "--port PORT");
            rwe("simulate", "cm11a", "--port", "tcp://127.0.0.1:" + port).assertReport("already in use", "--port PORT");
            rwe("simulate", "robot", "--config", ProjectFiles.resolve("docs/examples/simulated-robot.sim").toString(),
                    "--port", "tcp://127.0.0.1:" + port).assertReport("already in use", "--port PORT");
        }
    }

    @Test
    void aMissingFileSaysNoSuchFile() {
        rwe("simulate", "robot", "--config", folder.resolve("nowhere.sim").toString())
                .assertReport("nowhere.sim: no such file", "no such file");
    }

    // ----- helpers -----

    /** What a run left: exit code and standard error. */
    private record Run(int exit, String stderr) {
        void assertReport(String what, String fix) {
            assertNotEquals(0, exit, stderr);
            List<String> lines = stderr.lines().filter(line -> !line.isBlank()).toList();
            assertTrue(lines.size() <= 3, "at most three lines:\n" + stderr);
            assertTrue(lines.stream().noneMatch(line -> line.strip().startsWith("at ")), "no stack frame:\n" + stderr);
            assertTrue(stderr.contains(what), "says what happened (" + what + "):\n" + stderr);
            assertTrue(stderr.contains(fix), "names the fix (" + fix + "):\n" + stderr);
        }
    }

    /** A generated program in its own JVM, with the class path ant run gives it. */
    private static Run program(Path project, String mainClass, String... properties) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString()));
        command.addAll(List.of(properties));
        command.addAll(List.of("-cp", project.resolve("build/classes") + File.pathSeparator + project.resolve("lib")
                + File.separator + "*", mainClass));
        Path err = Files.createTempFile(folder, "stderr", ".txt");
        Process process = new ProcessBuilder(command).directory(project.toFile())
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(err.toFile()).start();
        if (!process.waitFor(120, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("the program did not end: " + Files.readString(err));
        }
        return new Run(process.exitValue(), Files.readString(err, StandardCharsets.UTF_8));
    }

    /** A verb's run; its report starts at "rwe VERB:" (explore shows its progress bar on standard error first). */
    private record Verb(int exit, String stderr) {
        void assertReport(String what, String fix) {
            int report = stderr.startsWith("rwe ") ? 0 : stderr.indexOf("\nrwe ") + 1;
            assertTrue(report >= 0, "no report:\n" + stderr);
            new Run(exit, stderr.substring(report)).assertReport(what, fix);
            assertTrue(stderr.substring(0, report).lines().noneMatch(l -> l.strip().startsWith("at ")), stderr);
        }
    }

    private static Verb rwe(String... args) {
        StringWriter err = new StringWriter();
        int exit = Rwe.run(new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), args);
        return new Verb(exit, err.toString());
    }

    private static int closedPort() {
        try (ServerSocket socket = new ServerSocket(0)) {
            return socket.getLocalPort();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A device that accepts connections and never says a word. */
    private static final class Silent implements AutoCloseable {
        private final ServerSocket server = new ServerSocket(0);
        private final List<Socket> accepted = new CopyOnWriteArrayList<>();

        Silent() throws IOException {
            Thread acceptor = new Thread(() -> {
                try {
                    while (true) {
                        accepted.add(server.accept());
                    }
                } catch (IOException closed) {
                    // the test is over
                }
            }, "silent-device");
            acceptor.setDaemon(true);
            acceptor.start();
        }

        int port() {
            return server.getLocalPort();
        }

        @Override
        public void close() throws IOException {
            server.close();
            for (Socket socket : accepted) {
                socket.close();
            }
        }
    }
}
