package robotworld.explorer.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.cli.Rwe;
import robotworld.space.Capi;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMModule;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMX10ApplianceModuleLocal;
import robotworld.xvsm.XVSMX10ApplianceModuleRemote;

/** The text view for headless machines: one line per call, from the API and from {@code rwe monitor --console}. */
class ConsoleMonitorTest {

    @Test
    void printsOneLinePerCallWithParticipantModuleFunctionAndValue() throws Exception {
        StringWriter text = new StringWriter();
        try (MonitoredSpace space = new MonitoredSpace()) {
            XVSMRuntime room = space.host("room-pc");
            XVSMRuntime robot = space.host("robot-laptop");
            XVSMRuntime laptop = space.host("laptop");
            new XVSMX10ApplianceModuleLocal(room, "DimRoom", "Lamp", new FakeHardware.Appliance());
            new XVSMBumperModuleLocal(robot, "CaterpillarRobot", "Bumper-Sensor", new FakeHardware.Bumper());
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.chapter5()));
            try (ConsoleMonitor monitor = new ConsoleMonitor(world, space.connection(), new PrintWriter(text))) {
                assertEquals(3, monitor.moduleCount());
                new XVSMX10ApplianceModuleRemote(laptop, "DimRoom", "Lamp").on();
                new XVSMBumperModuleRemote(laptop, "CaterpillarRobot", "Bumper-Sensor").getSingleBumper(4);
                waitFor(() -> text.toString().lines().count() >= 2);
            }
        }
        // each module's answers come through its own container's notifications: in order per module, but two
        // modules' lines may come in either order on a busy machine
        List<String> lines = text.toString().lines().toList();
        assertEquals(2, lines.size(), text.toString());
        assertTrue(lines.stream().anyMatch(line -> line.matches(
                "\\d\\d:\\d\\d:\\d\\d\\.\\d{3}  DimRoom +Lamp +on +\\(laptop\\)")), text.toString());
        assertTrue(lines.stream().anyMatch(line -> line.matches(
                ".*CaterpillarRobot +Bumper-Sensor +getSingleBumper +<4, 1>  \\(laptop\\)")), text.toString());
    }

    @Test
    void showsTheLastCallsMadeBeforeMonitoringStarted() throws Exception {
        StringWriter text = new StringWriter();
        try (MonitoredSpace space = new MonitoredSpace()) {
            XVSMRuntime room = space.host("room-pc");
            XVSMRuntime laptop = space.host("laptop");
            XVSMX10ApplianceModuleLocal lamp = new XVSMX10ApplianceModuleLocal(room, "DimRoom", "Lamp",
                    new FakeHardware.Appliance());
            lamp.on(); // a local call, published under the host's own name
            Capi connection = space.connection();
            connection.read(connection.lookupContainer(XVSMModule.answerContainerName("DimRoom", "Lamp")),
                    Timeout.ofMillis(5_000), Selector.lifo()); // published (asynchronously)
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.chapter5()));
            try (ConsoleMonitor monitor = new ConsoleMonitor(world, space.connection(), new PrintWriter(text))) {
                new XVSMX10ApplianceModuleRemote(laptop, "DimRoom", "Lamp").off();
                waitFor(() -> text.toString().lines().count() >= 2);
            }
        }
        String[] lines = text.toString().split("\n");
        assertEquals(2, lines.length, text.toString());
        assertTrue(lines[0].matches("earlier +DimRoom +Lamp +on +\\(room-pc\\)"), lines[0]);
        assertTrue(lines[1].matches("\\d\\d:\\d\\d:\\d\\d\\.\\d{3}  DimRoom +Lamp +off +\\(laptop\\)"), lines[1]);
    }

    @Test
    void rweMonitorConsoleRunsForTheGivenTime() throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        try (MonitoredSpace space = new MonitoredSpace()) {
            XVSMRuntime room = space.host("room-pc");
            XVSMRuntime laptop = space.host("laptop");
            new XVSMX10ApplianceModuleLocal(room, "DimRoom", "Lamp", new FakeHardware.Appliance());
            AtomicInteger exit = new AtomicInteger(-1);
            AtomicReference<Throwable> failure = new AtomicReference<>();
            Thread command = new Thread(() -> {
                try {
                    exit.set(Rwe.run(new PrintWriter(out, true), new PrintWriter(err, true), "monitor", "--console",
                            "--space", space.url(), "--for", "30", MonitorTestWorlds.chapter5().toString()));
                } catch (Throwable e) {
                    failure.set(e);
                }
            }, "rwe monitor");
            command.start();
            waitFor(() -> err.toString().contains("monitoring 3 modules"));
            XVSMX10ApplianceModuleRemote lamp = new XVSMX10ApplianceModuleRemote(laptop, "DimRoom", "Lamp");
            lamp.on();
            lamp.off();
            waitFor(() -> out.toString().contains(" off "));
            command.interrupt(); // as Ctrl-C would, without ending the test JVM
            command.join(5_000);
            assertEquals(0, exit.get(), err.toString());
            assertEquals(null, failure.get());
        }
        assertTrue(out.toString().contains("DimRoom") && out.toString().contains(" on "), out.toString());
    }

    @Test
    void changesOnlyPrintsAValueOncePerChannelAndMotorSpeedsAreMinusOneToOne() throws Exception {
        StringWriter text = new StringWriter();
        try (MonitoredSpace space = new MonitoredSpace()) {
            XVSMRuntime robot = space.host("robot-laptop");
            XVSMRuntime laptop = space.host("laptop");
            new robotworld.xvsm.XVSMMotorModuleLocal(robot, "CaterpillarRobot", "Motor-Controller",
                    new FakeHardware.Motor());
            new XVSMBumperModuleLocal(robot, "CaterpillarRobot", "Bumper-Sensor", new FakeHardware.Bumper());
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.chapter5()));
            try (ConsoleMonitor monitor = new ConsoleMonitor(world, space.connection(), new PrintWriter(text),
                    new ConsoleMonitor.Options(true, false))) {
                robotworld.core.MotorModule motor = new robotworld.xvsm.XVSMMotorModuleRemote(laptop,
                        "CaterpillarRobot", "Motor-Controller");
                XVSMBumperModuleRemote bumper = new XVSMBumperModuleRemote(laptop, "CaterpillarRobot", "Bumper-Sensor");
                for (int i = 0; i < 5; i++) { // a polling loop: the same commands and readings again and again
                    motor.setMotor(1, 0.25);
                    motor.setMotor(2, 0.25);
                    bumper.getSingleBumper(4);
                }
                motor.setMotor(1, -0.3);
                waitFor(() -> text.toString().contains("-0.300") && text.toString().contains("getSingleBumper"));
            }
        }
        // in order per module; the bumper's line may come before or after the motor's on a busy machine (each
        // module's answers come through its own container's notifications)
        List<String> lines = text.toString().lines().toList();
        assertEquals(4, lines.size(), text.toString());
        List<String> motorLines = lines.stream().filter(line -> line.contains("Motor-Controller")).toList();
        assertEquals(3, motorLines.size(), text.toString());
        assertTrue(motorLines.get(0).matches(".*Motor-Controller +setMotor +1 \\+0\\.250  \\(laptop\\)"),
                motorLines.get(0));
        assertTrue(motorLines.get(1).matches(".*setMotor +2 \\+0\\.250 .*"), motorLines.get(1));
        assertTrue(motorLines.get(2).matches(".*setMotor +1 -0\\.300 .*"), motorLines.get(2));
        assertEquals(1, lines.stream().filter(line -> line.matches(".*Bumper-Sensor +getSingleBumper +<4, 1> .*"))
                .count(), text.toString());
    }

    @Test
    void compactModePrintsOneLinePerSecondAndModuleChoosesWhatIsWatched() throws Exception {
        StringWriter text = new StringWriter();
        try (MonitoredSpace space = new MonitoredSpace()) {
            XVSMRuntime robot = space.host("robot-laptop");
            XVSMRuntime laptop = space.host("laptop");
            new XVSMBumperModuleLocal(robot, "CaterpillarRobot", "Bumper-Sensor", new FakeHardware.Bumper());
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.chapter5()))
                    .only(List.of("Bumper-Sensor"));
            assertEquals(1, world.moduleCount());
            int calls = 0;
            long opened = System.nanoTime();
            try (ConsoleMonitor monitor = new ConsoleMonitor(world, space.connection(), new PrintWriter(text),
                    new ConsoleMonitor.Options(false, true))) {
                XVSMBumperModuleRemote bumper = new XVSMBumperModuleRemote(laptop, "CaterpillarRobot", "Bumper-Sensor");
                long until = System.nanoTime() + 2_300_000_000L;
                while (System.nanoTime() < until || calls < 20) { // a 20 Hz poll, 20 calls at least
                    bumper.getSingleBumper(6);
                    calls++;
                    Thread.sleep(50);
                }
                waitFor(() -> text.toString().contains("calls, last getSingleBumper <6, 1>"));
            }
            long seconds = (System.nanoTime() - opened) / 1_000_000_000L;
            List<String> lines = text.toString().lines().toList();
            // at most one line per second that passed (however long a busy machine made it), fewer than calls
            assertTrue(lines.size() >= 1 && lines.size() <= seconds + 1 && lines.size() < calls,
                    "one line per second, not per call: " + calls + " calls in " + seconds + " s:\n" + text);
        }
        List<String> lines = text.toString().lines().toList();
        assertTrue(lines.stream().anyMatch(line -> line.matches(
                "\\d\\d:\\d\\d:\\d\\d  Bumper-Sensor \\d+ calls, last getSingleBumper <6, 1>  \\| alive: CaterpillarRobot")),
                text.toString());
        IllegalArgumentException refused = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.chapter5())).only(List.of("Nose")));
        assertTrue(refused.getMessage().startsWith("no module Nose in Chapter5World; its modules: DimRoom/Lamp, "),
                refused.getMessage());
    }

    private static void waitFor(java.util.function.BooleanSupplier condition) throws InterruptedException {
        // a bound for a monitor that never prints, not a speed claim: a busy machine may take seconds
        long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("condition not met within 60 s");
            }
            Thread.sleep(10);
        }
    }
}
