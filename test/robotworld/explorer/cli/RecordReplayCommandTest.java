package robotworld.explorer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldLayouts;
import robotworld.observe.AnswerSeen;
import robotworld.observe.ModuleRef;
import robotworld.observe.RequestSeen;
import robotworld.observe.WorldLayout;
import robotworld.recording.Recorder;
import robotworld.recording.mcap.McapPeer;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Timeout;
import robotworld.space.server.SpaceServer;
import robotworld.telemetry.Schemas;
import robotworld.telemetry.TrafficJson;
import robotworld.testsupport.ProjectFiles;
import robotworld.testsupport.RunningRwe;
import robotworld.testsupport.ThreadsLeft;
import robotworld.xvsm.CallTuple;

/** rwe record, rwe record --info and rwe replay as a person runs them. */
class RecordReplayCommandTest {

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    @TempDir
    Path folder;

    private int rwe(String... args) {
        return Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void recordsAWorldForADurationDescribesTheFileAndReplaysItToTheConsole() throws Exception {
        Path world = ProjectFiles.resolve("docs/examples/chapter5-world.xml");
        Path file = folder.resolve("run.mcap");
        try (EmbeddedSpace data = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(data, SpaceServer.Options.defaults().port(0)
                     .stopGraceMillis(200))) {
            CompletableFuture<Integer> recording = CompletableFuture.supplyAsync(() -> rwe("record",
                    world.toString(), "--out", file.toString(), "--duration", "3", "--space",
                    server.uri().toString()));
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (!err.toString().contains("recording 3 modules")) {
                assertTrue(System.nanoTime() < deadline && !recording.isDone(), "not recording: " + out + err);
                Thread.sleep(10);
            }
            // the robot's program publishes two local calls, as its Local side does
            ContainerRef answers = data.lookupOrCreateContainer(ContainerSpec.of(Order.LIFO).withKeyView()
                    .unbounded().named("CaterpillarRobotMotor-ControllerANSWER"));
            data.shift(answers, Timeout.TRY_ONCE, List.of(Item.keyed("robot-laptop",
                    CallTuple.of("robot-laptop", "setMotor", 1, 500).toTuple())));
            Thread.sleep(200);
            data.shift(answers, Timeout.TRY_ONCE, List.of(Item.keyed("robot-laptop",
                    CallTuple.of("robot-laptop", "setMotor", 1, 0).toTuple())));
            assertEquals(0, recording.get(60, TimeUnit.SECONDS), err.toString());
        }
        assertTrue(out.toString().contains("recorded ") && out.toString().contains("nothing dropped"), out.toString());
        assertTrue(Files.size(file) > 0);

        out.getBuffer().setLength(0);
        assertEquals(0, rwe("record", "--info", file.toString()), err.toString());
        String info = out.toString();
        assertTrue(info.contains("finished MCAP file"), info);
        assertTrue(info.contains("world        Chapter5World"), info);
        assertTrue(info.matches("(?s).*/CaterpillarRobot/Motor-Controller\\s+rwe.ModuleTraffic\\s+json\\s+2\\n.*"),
                info);
        assertTrue(info.contains("/rwe/liveness") && info.contains("ended: --duration reached"), info);
        assertTrue(info.contains("attachments  rwe-layout.json") && info.contains("world.xml"), info);

        out.getBuffer().setLength(0);
        assertEquals(0, rwe("replay", file.toString(), "--console", "--foxglove-port", "-1", "--rate", "4", "-q"),
                err.toString());
        String replay = out.toString();
        assertTrue(replay.contains("# REPLAY of run.mcap"), replay);
        assertTrue(replay.matches("(?s).*CaterpillarRobot\\s+Motor-Controller\\s+setMotor\\s+.*500.*"), replay);
        assertTrue(replay.contains("replay space at http://127.0.0.1:"), replay);
        assertTheReferenceReaderAgrees(file);
    }

    @Test
    void ctrlCFinishesTheFileAndPrintsTheSummary() throws Exception {
        Path world = ProjectFiles.resolve("docs/examples/chapter5-world.xml");
        Path file = folder.resolve("interrupted.mcap");
        Path stdout = folder.resolve("record.out");
        Path stderr = folder.resolve("record.err");
        try (EmbeddedSpace data = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(data, SpaceServer.Options.defaults().port(0)
                     .stopGraceMillis(200))) {
            // the real command in a JVM of its own (the built jar, as ./rwe starts it), as a person runs it
            Path jar = Path.of(System.getProperty("rwe.build.dir", "build"), "dist", "robotworldexplorer.jar");
            List<String> command = new ArrayList<>();
            if (ignoresSigint()) {
                // started in the background of a non-interactive shell: our children would ignore Ctrl-C too
                command.addAll(List.of("env", "--default-signal=INT"));
            }
            command.addAll(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-Drwe.home=" + ProjectFiles.root(), "-jar", jar.toAbsolutePath().toString(), "record",
                    world.toString(), "--out", file.toString(), "--space", server.uri().toString()));
            Process process = new ProcessBuilder(command).directory(ProjectFiles.root().toFile())
                    .redirectOutput(stdout.toFile()).redirectError(stderr.toFile()).start();
            try {
                long deadline = System.nanoTime() + 60_000_000_000L;
                while (!read(stderr).contains("recording 3 modules")) {
                    assertTrue(System.nanoTime() < deadline && process.isAlive(), "not recording: " + read(stdout)
                            + read(stderr));
                    Thread.sleep(20);
                }
                long before = progressCount(stderr, deadline, process);
                ContainerRef answers = data.lookupOrCreateContainer(ContainerSpec.of(Order.LIFO).withKeyView()
                        .unbounded().named("CaterpillarRobotMotor-ControllerANSWER"));
                data.shift(answers, Timeout.TRY_ONCE, List.of(Item.keyed("robot-laptop",
                        CallTuple.of("robot-laptop", "setMotor", 1, 500).toTuple())));
                Thread.sleep(200);
                data.shift(answers, Timeout.TRY_ONCE, List.of(Item.keyed("robot-laptop",
                        CallTuple.of("robot-laptop", "setMotor", 1, 0).toTuple())));
                // the progress line (once a second) counts both calls: they are in the recorder
                while (progressCount(stderr, deadline, process) < before + 2) {
                    assertTrue(System.nanoTime() < deadline && process.isAlive(), "the calls were not recorded: "
                            + read(stderr));
                    Thread.sleep(50);
                }
                Process kill = new ProcessBuilder("kill", "-INT", String.valueOf(process.pid())).inheritIO().start();
                assertEquals(0, kill.waitFor(), "kill -INT");
                assertTrue(process.waitFor(60, TimeUnit.SECONDS), "rwe record did not stop on Ctrl-C: " + read(stderr));
            } finally {
                process.destroyForcibly();
            }
            assertEquals(130, process.exitValue(), "ended by SIGINT, as after Ctrl-C: " + read(stderr));
        }
        String summary = read(stdout);
        assertTrue(summary.matches("(?s)recorded \\d+ messages, .* into " + java.util.regex.Pattern.quote(
                file.toString()) + "; nothing dropped\\R"), "the summary line: '" + summary + "'\n" + read(stderr));

        out.getBuffer().setLength(0);
        assertEquals(0, rwe("record", "--info", file.toString()), err.toString());
        String info = out.toString();
        assertTrue(info.contains(": finished MCAP file"), info);
        assertTrue(info.contains("ended: Ctrl-C"), info);
        assertTrue(info.matches("(?s).*/CaterpillarRobot/Motor-Controller\\s+rwe.ModuleTraffic\\s+json\\s+2\\n.*"),
                info);
        assertTrue(info.contains("indexed      yes"), info);
        assertTheReferenceReaderAgrees(file);
    }

    @Test
    void aFileTheReferencePythonWriterWroteReplaysToTheConsoleInOrder() throws Exception {
        // a user's script: the Python mcap package's Writer with its defaults (zstd chunks), our topics and schemas
        Path file = folder.resolve("python.mcap");
        McapPeer.require().write(file, pythonRecording(), folder);

        assertEquals(0, rwe("record", "--info", file.toString()), err.toString());
        String info = out.toString();
        assertTrue(info.contains("written by python mcap peer"), info);
        assertTrue(info.matches("(?s).*/CaterpillarRobot/Motor-Controller\\s+rwe.ModuleTraffic\\s+json\\s+6\\n.*"),
                info);
        assertTrue(info.matches("(?s).*/CaterpillarRobot/Bumper-Sensor\\s+rwe.ModuleTraffic\\s+json\\s+2\\n.*"),
                info);

        out.getBuffer().setLength(0);
        assertEquals(0, rwe("replay", file.toString(), "--console", "--foxglove-port", "-1", "-q"), err.toString());
        String replay = out.toString();
        // every request and answer is played, over the time the log times span
        assertTrue(replay.contains("replaying " + file + ": 8 messages over 0.3 s"), replay);
        assertTrue(replay.contains("# REPLAY of python.mcap"), replay);
        // the console prints answers; each module's answers keep their recorded order
        assertEquals(List.of("setMotor 1 +0.250", "setMotor 1 -0.400", "setMotor 1 +0.000"),
                answers(replay, "Motor-Controller"));
        assertEquals(List.of("getAllBumper 40"), answers(replay, "Bumper-Sensor"));
    }

    /** The console lines of {@link #recordMotorCalls}' four answers, in the recorded order. */
    private static final List<String> LOOPED = List.of("setMotor 1 +0.250", "setMotor 1 -0.400", "setMotor 1 +0.100",
            "setMotor 1 +0.000");

    @Test
    void replayWithLoopPlaysTheRunAgainAndAgainAsAReplayUntilCtrlC() throws Exception {
        Path file = folder.resolve("loop.mcap");
        recordMotorCalls(file);
        Set<Thread> before = ThreadsLeft.now();
        RunningRwe replay = new RunningRwe("replay", file.toString(), "--loop", "--rate", "4", "--console",
                "--foxglove-port", "-1");
        RunningRwe watcher = null;
        try {
            String space = replay.await("(?m)^replay space at (http://\\S+)$");
            assertFalse(ThreadsLeft.since(before, name -> name.startsWith("space-server")).isEmpty(),
                    "the replay's own threads are told apart");
            assertTrue(replay.out.toString().contains("replaying " + file + ": 8 messages over 0.3 s of Chapter5World,"
                    + " at 4x, looping"), replay.toString());
            // the console here: the run twice at least, in order, after the mark
            replay.awaitTrue(() -> answers(replay.out.toString(), "Motor-Controller").size() >= 2 * LOOPED.size(),
                    "the recorded calls twice");
            assertTrue(replay.out.toString().contains("# REPLAY of loop.mcap (recorded "), replay.toString());
            assertTrue(replay.out.toString().indexOf("# REPLAY of loop.mcap") < replay.out.toString()
                    .indexOf("Motor-Controller"), "marked before the first call: " + replay);
            List<String> seen = answers(replay.out.toString(), "Motor-Controller");
            for (int i = 0; i < seen.size(); i++) {
                assertEquals(LOOPED.get(i % LOOPED.size()), seen.get(i), "pass after pass, in order: " + seen);
            }
            // the progress line counts the passes
            replay.awaitTrue(() -> lastPass(replay.err.toString()) >= 3, "a progress line of pass 3 or later");

            // someone who starts watching now, in a later pass, with the command the replay printed, is told too
            Matcher watch = Pattern.compile("(?m)^watch it: rwe monitor (\\S+) --space (\\S+)$")
                    .matcher(replay.out.toString());
            assertTrue(watch.find(), replay.toString());
            assertEquals(space, watch.group(2));
            watcher = new RunningRwe("monitor", watch.group(1), "--space", space, "--console");
            RunningRwe late = watcher;
            late.awaitTrue(() -> live(late).size() >= 2 * LOOPED.size(), "the watcher seeing two passes");
            assertTrue(late.out.toString().startsWith("# REPLAY of loop.mcap (recorded "), late.toString());
            List<String> watched = live(late);
            int first = LOOPED.indexOf(watched.get(0));
            for (int i = 0; i < watched.size(); i++) {
                assertEquals(LOOPED.get((first + i) % LOOPED.size()), watched.get(i), "in order: " + watched);
            }
            assertEquals(0, late.stop(10_000), late.toString());

            long stopping = System.nanoTime();
            assertEquals(0, replay.stop(10_000), replay.toString());
            long stoppedMillis = (System.nanoTime() - stopping) / 1_000_000;
            assertTrue(stoppedMillis < 5_000, "Ctrl-C took " + stoppedMillis + " ms" + replay);
            assertTrue(replay.err.toString().matches("(?s).*\\nreplay stopped after \\d+\\.\\d s\\n"),
                    replay.toString());
            // the replay space is gone with it
            URI uri = URI.create(space);
            try (Socket socket = new Socket()) {
                socket.connect(new InetSocketAddress(uri.getHost(), uri.getPort()), 5_000);
                throw new AssertionError("the replay space still listens at " + space);
            } catch (ConnectException expected) {
                // closed
            }
        } finally {
            replay.close();
            if (watcher != null) {
                watcher.close();
            }
        }
        // nothing of it runs on: its space server, console monitor, taps, the watcher (the JVM's shared pools aside)
        ThreadsLeft.assertNoneSince(before, name -> !name.startsWith("ForkJoinPool.commonPool")
                && !name.equals("process reaper"));
    }

    /** The motor answers a console monitor printed as they came (not those it found there when it started). */
    private static List<String> live(RunningRwe monitor) {
        return answers(monitor.out.toString().lines().filter(line -> !line.startsWith("earlier"))
                .collect(java.util.stream.Collectors.joining("\n")), "Motor-Controller");
    }

    /** The highest pass number of the progress lines so far, 0 when there is none. */
    private static int lastPass(String err) {
        Matcher pass = Pattern.compile("\\rpass (\\d+): ").matcher(err);
        int last = 0;
        while (pass.find()) {
            int number = Integer.parseInt(pass.group(1));
            assertTrue(number >= last, "pass numbers only grow: " + err);
            last = number;
        }
        return last;
    }

    /**
     * A run of Chapter5World as {@code rwe record} writes it, with our Recorder: four calls of the laptop setting
     * motor 1 to 250, -400, 100 and 0 per mille, 100 ms apart, each answered 10 ms after its request.
     */
    private static void recordMotorCalls(Path file) throws Exception {
        Path description = ProjectFiles.resolve("docs/examples/chapter5-world.xml");
        WorldLayout layout = WorldLayouts.of(MonitoredWorld.of(DescriptionLoader.loadWorld(description)));
        ModuleRef motor = layout.modules().stream().filter(m -> m.name().equals("Motor-Controller")).findFirst()
                .orElseThrow();
        int[] speeds = {250, -400, 100, 0};
        Instant t0 = Instant.parse("2026-01-05T10:00:00Z");
        try (Recorder recorder = Recorder.start(file, new Recorder.Start(layout, "http://127.0.0.1:9876/space",
                Files.readAllBytes(description)), Recorder.Options.defaults())) {
            for (int i = 0; i < speeds.length; i++) {
                CallTuple call = CallTuple.of("laptop#loop." + i, "setMotor", 1, speeds[i]);
                Instant asked = t0.plusMillis(100L * i);
                recorder.observer().requestSeen(new RequestSeen(motor, call, asked, 1));
                recorder.observer().answerSeen(new AnswerSeen(motor, call, asked.plusMillis(10), false,
                        Duration.ofMillis(10), 0));
            }
        }
    }

    /**
     * Three motor calls (speed 250, -400 and 0 per mille) and a bumper read answering 40, each request followed by
     * its answer 10 ms later, 100 ms apart, with the world's description attached as {@code rwe record} does.
     */
    private static ObjectNode pythonRecording() throws Exception {
        ObjectNode spec = TrafficJson.MAPPER.createObjectNode();
        spec.put("compression", "default");
        spec.putArray("schemas").addObject().put("name", "rwe.ModuleTraffic").put("encoding", "jsonschema")
                .put("data", Schemas.text("rwe.ModuleTraffic"));
        ArrayNode channels = spec.putArray("channels");
        for (String module : List.of("Motor-Controller", "Bumper-Sensor")) {
            channels.addObject().put("topic", "/CaterpillarRobot/" + module).put("message_encoding", "json")
                    .put("schema", "rwe.ModuleTraffic");
        }
        long t0 = 1_764_000_000_000_000_000L;
        spec.putArray("attachments").addObject().put("name", "world.xml").put("media_type", "application/xml")
                .put("log_time", t0).put("data", Files.readString(ProjectFiles.resolve(
                        "docs/examples/chapter5-world.xml")));
        ArrayNode messages = spec.putArray("messages");
        int[] speeds = {250, -400, 0};
        for (int i = 0; i < speeds.length; i++) {
            call(messages, t0 + i * 100_000_000L, "Motor-Controller", "MotorModule", "laptop#a." + i, "setMotor",
                    List.of(1, speeds[i]), List.of(1, speeds[i]));
        }
        call(messages, t0 + 300_000_000L, "Bumper-Sensor", "BumperModule", "laptop#a.3", "getAllBumper",
                List.of(0), List.of(40));
        return spec;
    }

    private static void call(ArrayNode messages, long at, String module,
            String moduleClass, String key, String function, List<Integer> arguments, List<Integer> values) {
        for (String kind : List.of("request", "answer")) {
            ObjectNode traffic = TrafficJson.MAPPER.createObjectNode()
                    .put("kind", kind).put("participant", "CaterpillarRobot").put("module", module)
                    .put("module_class", moduleClass).put("key", key).put("host", "laptop").put("function", function);
            (kind.equals("request") ? arguments : values).forEach(traffic.putArray("fields")::add);
            messages.addObject().put("topic", "/CaterpillarRobot/" + module)
                    .put("log_time", kind.equals("request") ? at : at + 10_000_000L).put("data", traffic.toString());
        }
    }

    /** The console monitor's answer lines of {@code module}, as "function value", in the order printed. */
    private static List<String> answers(String console, String module) {
        List<String> found = new ArrayList<>();
        java.util.regex.Matcher line = java.util.regex.Pattern.compile("(?m)^\\S+\\s+CaterpillarRobot\\s+"
                + java.util.regex.Pattern.quote(module) + "\\s+(\\S+)\\s+(.*?)\\s+\\(laptop\\)$").matcher(console);
        while (line.find()) {
            found.add(line.group(1) + " " + line.group(2));
        }
        return found;
    }

    /**
     * The reference Python reader (test-setup/requirements.txt) reads the file {@code rwe record} wrote, checking
     * every CRC: a summary with statistics, a footer, the index and a linear read giving the same messages, and the
     * two motor calls on their module's topic.
     */
    private static void assertTheReferenceReaderAgrees(Path file) throws Exception {
        JsonNode found = McapPeer.require().read(file);
        long count = found.at("/summary/statistics/message_count").asLong();
        assertTrue(count >= 2, found.toString());
        assertEquals(count, found.get("indexed").size(), "messages read through the index");
        assertEquals(count, found.get("streamed").size(), "messages read as a stream");
        assertTrue(found.get("footer").asBoolean(), "a footer");
        assertTrue(found.at("/summary/chunk_indexes").asInt() >= 1, "chunk indexes");
        long motorCalls = 0;
        for (JsonNode message : found.get("indexed")) {
            if (message.get("topic").asText().equals("/CaterpillarRobot/Motor-Controller")) {
                motorCalls++;
            }
        }
        assertEquals(2, motorCalls, "the two motor calls, as the reference reader sees them");
    }

    /** The message count of the last progress line, once there is one. */
    private static long progressCount(Path stderr, long deadline, Process process) throws Exception {
        java.util.regex.Pattern count = java.util.regex.Pattern.compile("s  (\\d+) messages  ");
        while (true) {
            java.util.regex.Matcher matcher = count.matcher(read(stderr));
            long last = -1;
            while (matcher.find()) {
                last = Long.parseLong(matcher.group(1));
            }
            if (last >= 0) {
                return last;
            }
            assertTrue(System.nanoTime() < deadline && process.isAlive(), "no progress line: " + read(stderr));
            Thread.sleep(50);
        }
    }

    /** Whether this JVM was started with SIGINT ignored (Linux), which its children would inherit. */
    private static boolean ignoresSigint() throws java.io.IOException {
        Path status = Path.of("/proc/self/status");
        if (!Files.exists(status)) {
            return false;
        }
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("SigIgn:")) {
                return (Long.parseUnsignedLong(line.substring(7).trim(), 16) & 0x2) != 0; // bit of signal 2
            }
        }
        return false;
    }

    private static String read(Path file) throws java.io.IOException {
        return Files.exists(file) ? Files.readString(file) : "";
    }

    @Test
    void mistakesGetOneLineNamingTheFix() throws Exception {
        Path notMcap = folder.resolve("notes.mcap");
        Files.writeString(notMcap, "not a recording");
        assertEquals(1, rwe("record", "--info", notMcap.toString()));
        assertTrue(err.toString().contains("is not an MCAP file"), err.toString());
        assertEquals(1, rwe("replay", folder.resolve("missing.mcap").toString()));
        assertTrue(err.toString().contains("no such file"), err.toString());
        assertEquals(2, rwe("record", "--out", folder.resolve("x.mcap").toString()));
        assertTrue(err.toString().contains("give WORLD and --out"), err.toString());
        assertEquals(2, rwe("replay", notMcap.toString(), "--rate", "0"));
        assertTrue(err.toString().contains("--rate"), err.toString());
        err.getBuffer().setLength(0);
        // a world whose space is not there
        int code = rwe("record", ProjectFiles.resolve("docs/examples/chapter5-world.xml").toString(), "--out",
                folder.resolve("y.mcap").toString(), "--space", "http://127.0.0.1:9/space", "--duration", "1");
        assertEquals(1, code, out + "" + err);
        assertTrue(err.toString().contains("rwe record: cannot") && err.toString().contains("--space URL"),
                err.toString());
        assertTrue(!Files.exists(folder.resolve("y.mcap")), "nothing recorded, nothing left behind");
        assertTrue(!err.toString().contains("\tat "), "no stack trace: " + err);

        // the Foxglove endpoint's port is taken (by an rwe bridge, say): the option to choose another is named
        Path recorded = folder.resolve("z.mcap");
        recordMotorCalls(recorded);
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            err.getBuffer().setLength(0);
            out.getBuffer().setLength(0);
            assertEquals(1, rwe("replay", recorded.toString(), "--foxglove-port", String.valueOf(taken.getLocalPort()),
                    "-q"), out + "" + err);
            // not --port: that is the replay space's
            assertEquals("rwe replay: cannot listen on 127.0.0.1:" + taken.getLocalPort() + " for Foxglove: Address"
                    + " already in use\nStop the program that uses it (another rwe bridge or rwe replay?), or choose"
                    + " another port with --foxglove-port P (0: any free one; -1: none).\n", err.toString());
        }
    }
}
