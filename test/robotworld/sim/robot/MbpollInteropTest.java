package robotworld.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.SocatPty;
import robotworld.testsupport.ProjectFiles;
import robotworld.testsupport.TestPeers;

/**
 * The simulator checked by an independent Modbus RTU master: mbpoll (libmodbus) on one end of a socat pty pair,
 * the simulated robot of {@code docs/examples/simulated-robot.sim} on the other.
 */
class MbpollInteropTest {

    private static final Pattern VALUE = Pattern.compile("^\\[(\\d+)\\]:\\s+(\\d+)", Pattern.MULTILINE);

    private SocatPty pty;
    private SimulatedRobot robot;

    /** Output and exit code of one mbpoll run. */
    private record Run(int exitCode, String output) {
        List<Integer> values() {
            List<Integer> values = new ArrayList<>();
            Matcher matcher = VALUE.matcher(output);
            while (matcher.find()) {
                values.add(Integer.parseInt(matcher.group(2)));
            }
            return values;
        }
    }

    @BeforeAll
    static void needsMbpoll() {
        TestPeers.requireCommand("mbpoll", "mbpoll");
    }

    @BeforeEach
    void start() throws Exception {
        pty = SocatPty.start();
        SimRobotConfig config = SimRobotConfigReader.read(ProjectFiles.resolve("docs/examples/simulated-robot.sim"))
                .withTiming(LineTiming.FAST);
        robot = SimulatedRobot.create(config);
        robot.serve(pty.a().toString());
    }

    @AfterEach
    void stop() throws Exception {
        robot.close();
        pty.close();
    }

    /** Runs mbpoll once on the master end: options, then the device, then values to write (if any). */
    private Run mbpoll(List<String> options, String... values) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of("mbpoll", "-m", "rtu", "-b", "115200", "-P", "none", "-1",
                "-o", "0.5"));
        command.addAll(options);
        command.add(pty.b().toString());
        command.addAll(List.of(values));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("mbpoll did not finish: " + command);
        }
        return new Run(process.exitValue(), new String(process.getInputStream().readAllBytes(),
                StandardCharsets.UTF_8));
    }

    @Test
    void readsTheBumpersAsDiscreteInputs() throws Exception {
        Run free = mbpoll(List.of("-a", "2", "-t", "1", "-r", "1", "-c", "8"));
        assertEquals(0, free.exitCode(), free.output());
        assertEquals(List.of(0, 0, 0, 0, 0, 0, 0, 0), free.values(), free.output());

        robot.simulation().inspect(world -> {
            world.place(new Pose(world.width() - world.radius(), 1000, 0)); // nose against the right wall
            return null;
        });
        Run touching = mbpoll(List.of("-a", "2", "-t", "1", "-r", "1", "-c", "8"));
        assertEquals(List.of(0, 0, 0, 1, 0, 1, 0, 0), touching.values(), touching.output());
    }

    @Test
    void readsIrDistancesAndRawReadingsAsInputRegisters() throws Exception {
        Run run = mbpoll(List.of("-a", "4", "-t", "3", "-r", "1", "-c", "14"));
        assertEquals(0, run.exitCode(), run.output());
        SimIRDistanceModule ir = (SimIRDistanceModule) robot.module(4);
        List<Integer> expected = new ArrayList<>();
        for (int sensor = 1; sensor <= 7; sensor++) {
            expected.add(ir.distance(sensor));
        }
        for (int sensor = 1; sensor <= 7; sensor++) {
            expected.add((int) Math.round(255.0 * (800 - ir.distance(sensor)) / 800));
        }
        assertEquals(expected, run.values(), run.output());
        assertEquals(800, expected.get(0), "nothing within range straight ahead");
    }

    @Test
    void writesAndReadsMotorSpeedsAsHoldingRegisters() throws Exception {
        Run write = mbpoll(List.of("-a", "1", "-t", "4", "-r", "1"), "500", "65036");
        assertEquals(0, write.exitCode(), write.output());
        SimMotorModule motor = (SimMotorModule) robot.module(1);
        assertEquals(500, motor.setSpeed(1));
        assertEquals(-500, motor.setSpeed(2));
        Run read = mbpoll(List.of("-a", "1", "-t", "4", "-r", "1", "-c", "2"));
        assertEquals(List.of(500, 65036), read.values(), read.output());
    }

    @Test
    void reportsServerIdWithRunIndicator() throws Exception {
        Run run = mbpoll(List.of("-a", "3", "-u"));
        assertEquals(0, run.exitCode(), run.output());
        assertTrue(run.output().contains("Id    : 0x03"), run.output());
        assertTrue(run.output().contains("Status: On"), run.output());
    }

    @Test
    void refusesOutOfRangeValuesAndStaysSilentForAbsentAddresses() throws Exception {
        Run refused = mbpoll(List.of("-a", "3", "-t", "4", "-r", "1"), "200");
        assertTrue(refused.output().contains("Illegal data value"), refused.output());
        Run absent = mbpoll(List.of("-a", "9", "-t", "1", "-r", "1"));
        assertTrue(absent.exitCode() != 0 && absent.output().contains("timed out"), absent.output());
    }
}
