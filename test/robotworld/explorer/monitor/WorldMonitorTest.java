package robotworld.explorer.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.eventually;
import static robotworld.explorer.gui.GuiTesting.onEdt;
import static robotworld.explorer.gui.GuiTesting.screenshot;
import static robotworld.explorer.monitor.MonitorTestWorlds.ROBOT;
import static robotworld.explorer.monitor.MonitorTestWorlds.ROOM;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.core.BumperModule;
import robotworld.core.IRDistanceModule;
import robotworld.core.MotorModule;
import robotworld.core.ServoModule;
import robotworld.core.X10ApplianceModule;
import robotworld.core.X10LampModule;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.gui.GuiTesting;
import robotworld.explorer.monitor.gui.BumperModulePanel;
import robotworld.explorer.monitor.gui.FreshnessLabel;
import robotworld.explorer.monitor.gui.IRDistanceModulePanel;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.explorer.monitor.gui.ModulePanel;
import robotworld.explorer.monitor.gui.MonitorWindow;
import robotworld.explorer.monitor.gui.ParticipantPanel;
import robotworld.explorer.monitor.gui.MotorModulePanel;
import robotworld.explorer.monitor.gui.OnOffIndicator;
import robotworld.explorer.monitor.gui.ParticipantWindow;
import robotworld.explorer.monitor.gui.PlotsPanel;
import robotworld.explorer.monitor.gui.ServoModulePanel;
import robotworld.explorer.monitor.gui.StatusStrip;
import robotworld.explorer.monitor.gui.X10ApplianceModulePanel;
import robotworld.explorer.monitor.gui.X10LampModulePanel;
import robotworld.observe.ModuleRef;
import robotworld.space.Capi;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMIRDistanceModuleLocal;
import robotworld.xvsm.XVSMIRDistanceModuleRemote;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMServoModuleLocal;
import robotworld.xvsm.XVSMServoModuleRemote;
import robotworld.xvsm.XVSMX10ApplianceModuleLocal;
import robotworld.xvsm.XVSMX10ApplianceModuleRemote;
import robotworld.xvsm.XVSMX10LampModuleLocal;
import robotworld.xvsm.XVSMX10LampModuleRemote;

/**
 * The monitoring windows of a running world, driven by real notifications: Local proxies on the modules' hosts,
 * remote calls from a laptop, all through a loopback space server; the monitor has a connection of its own.
 */
class WorldMonitorTest {

    @TempDir
    Path folder;

    private MonitoredSpace space;
    private XVSMRuntime room;
    private XVSMRuntime robot;
    private XVSMRuntime laptop;
    private WorldMonitor monitor;
    private final FakeHardware.Bumper bumperHardware = new FakeHardware.Bumper();

    @BeforeEach
    void start() throws Exception {
        GuiTesting.assumeDisplay();
        space = new MonitoredSpace();
        room = space.host("room-pc");
        robot = space.host("robot-laptop");
        laptop = space.host("laptop");
        new XVSMX10ApplianceModuleLocal(room, ROOM, "Lamp", new FakeHardware.Appliance());
        new XVSMX10LampModuleLocal(room, ROOM, "Ceiling", new FakeHardware.Lamp());
        new XVSMMotorModuleLocal(robot, ROBOT, "Motor-Controller", new FakeHardware.Motor());
        new XVSMBumperModuleLocal(robot, ROBOT, "Bumper-Sensor", bumperHardware);
        new XVSMServoModuleLocal(robot, ROBOT, "Head-Servo", new FakeHardware.Servo());
        new XVSMIRDistanceModuleLocal(robot, ROBOT, "IR-Sensors", new FakeHardware.IR());
        MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.everyModuleType(folder)));
        monitor = onEdt(() -> {
            WorldMonitor opened = new WorldMonitor(world, space.connection(), new MonitorLoader());
            opened.show();
            return opened;
        });
        assertTrue(monitor.awaitWatching(Duration.ofSeconds(10)), "every monitor watches its module");
    }

    @AfterEach
    void stop() throws Exception {
        if (monitor != null) {
            onEdt(monitor::close);
        }
        if (space != null) {
            space.close();
        }
    }

    @Test
    void oneWindowWithTheWorldViewPlotsATabPerParticipantAndTheStatusStrip() {
        MonitorWindow window = monitor.window();
        assertEquals("Monitor: Chapter5World - RobotWorldExplorer", onEdt(window::getTitle));
        assertEquals(List.of("DimRoom", "CaterpillarRobot"), onEdt(() -> List.of(window.tabs().getTitleAt(0),
                window.tabs().getTitleAt(1))));
        assertEquals(List.of(X10ApplianceModulePanel.class, X10LampModulePanel.class, MotorModulePanel.class,
                        BumperModulePanel.class, ServoModulePanel.class, IRDistanceModulePanel.class),
                monitor.monitors().stream().map(m -> m.getPanel().getClass()).toList());
        assertEquals(FreshnessLabel.NO_REPORT, onEdt(() -> panel(X10ApplianceModulePanel.class).freshness().getText()));
        assertTrue(onEdt(() -> window.getWidth() >= 800 && window.getHeight() >= 560), "a sensible default size");
        assertTrue(monitor.windows().isEmpty());
    }

    @Test
    void theThesisLayoutOfOneWindowPerParticipantIsStillThere() throws Exception {
        MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.everyModuleType(folder)));
        WorldMonitor perParticipant = onEdt(() -> new WorldMonitor(world, space.connection(), new MonitorLoader(),
                WorldMonitor.Windows.PER_PARTICIPANT, LayoutMemory.none()));
        try {
            List<ParticipantWindow> windows = perParticipant.windows();
            assertEquals(2, windows.size());
            assertEquals("Monitor: DimRoom (environment) - Chapter5World", windows.get(0).getTitle());
            assertEquals("Monitor: CaterpillarRobot (robot) - Chapter5World", windows.get(1).getTitle());
            assertTrue(onEdt(() -> windows.get(0).getWidth() >= 460 && windows.get(0).getHeight() >= 260),
                    "no clipped sliver of a window");
            assertEquals(null, perParticipant.window());
        } finally {
            onEdt(perParticipant::close);
        }
    }

    @Test
    void aRemoteCallSwitchesTheApplianceOnAndOff() {
        X10ApplianceModule lamp = new XVSMX10ApplianceModuleRemote(laptop, ROOM, "Lamp");
        X10ApplianceModulePanel panel = panel(X10ApplianceModulePanel.class);
        assertEquals(OnOffIndicator.State.UNKNOWN, onEdt(() -> panel.indicator().state()));

        lamp.on();
        eventually("the panel shows ON", () -> panel.indicator().state() == OnOffIndicator.State.ON);
        assertEquals("ON", onEdt(() -> panel.indicator().stateText()));
        assertTrue(onEdt(() -> panel.freshness().getText()).startsWith("last report "),
                onEdt(() -> panel.freshness().getText()));
        assertTrue(onEdt(() -> panel.freshness().getText()).contains("for laptop"));
        screenshot(panel, "panel-x10-appliance-on");

        lamp.off();
        eventually("the panel shows OFF", () -> panel.indicator().state() == OnOffIndicator.State.OFF);
        assertEquals("OFF", onEdt(() -> panel.indicator().stateText()));
    }

    @Test
    void theLampLevelIsTheSumOfTheChanges() {
        X10LampModule lamp = new XVSMX10LampModuleRemote(laptop, ROOM, "Ceiling");
        X10LampModulePanel panel = panel(X10LampModulePanel.class);
        lamp.on();
        eventually("on at full brightness", () -> panel.sliderValue() == 100);
        lamp.dim(30);
        eventually("dimmed to 70 %", () -> panel.sliderValue() == 70);
        lamp.brighten(10);
        eventually("brightened to 80 %", () -> panel.sliderValue() == 80);
        screenshot(panel, "panel-x10-lamp");
        lamp.off();
        eventually("off", () -> panel.indicator().state() == OnOffIndicator.State.OFF && panel.sliderValue() == 0);
    }

    @Test
    void everyPanelShowsItsModule() {
        new XVSMX10ApplianceModuleRemote(laptop, ROOM, "Lamp").on();
        X10LampModule ceiling = new XVSMX10LampModuleRemote(laptop, ROOM, "Ceiling");
        ceiling.on();
        ceiling.dim(40);
        MotorModule motor = new XVSMMotorModuleRemote(laptop, ROBOT, "Motor-Controller");
        ServoModule servo = new XVSMServoModuleRemote(laptop, ROBOT, "Head-Servo");
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper-Sensor");
        IRDistanceModule ir = new XVSMIRDistanceModuleRemote(laptop, ROBOT, "IR-Sensors");

        motor.setMotor(1, 0.5);
        motor.setMotorQuiet(2, -0.25);
        servo.setServo(3, 90);
        bumper.getAllBumper();
        ir.getAllSensors();
        ir.getSingleSensor(2);

        MotorModulePanel motors = panel(MotorModulePanel.class);
        ServoModulePanel servos = panel(ServoModulePanel.class);
        BumperModulePanel bumpers = panel(BumperModulePanel.class);
        IRDistanceModulePanel distances = panel(IRDistanceModulePanel.class);
        eventually("motor speeds", () -> motors.valueText(1).equals("+0.500") && motors.valueText(2).equals("-0.250"));
        eventually("servo position", () -> servos.valueText(3).equals("90°"));
        eventually("bumper colours", () -> bumpers.colourOf(4).equals(BumperModulePanel.CONTACT)
                && bumpers.colourOf(6).equals(BumperModulePanel.CONTACT)
                && bumpers.colourOf(1).equals(BumperModulePanel.FREE));
        eventually("IR distances", () -> distances.valueText(1).equals("120 mm")
                && distances.valueText(7).equals("75 mm"));
        assertEquals(ServoModulePanel.UNKNOWN, onEdt(() -> servos.valueText(1)), "servo 1 was never set");
        X10ApplianceModulePanel appliance = panel(X10ApplianceModulePanel.class);
        X10LampModulePanel lamp = panel(X10LampModulePanel.class);
        eventually("room modules", () -> appliance.indicator().state() == OnOffIndicator.State.ON
                && lamp.sliderValue() == 60);

        // a single bumper turning free changes only its own field
        bumperHardware.mask.set(1 << 5);
        bumper.getSingleBumper(4);
        eventually("bumper 4 free", () -> bumpers.colourOf(4).equals(BumperModulePanel.FREE)
                && bumpers.colourOf(6).equals(BumperModulePanel.CONTACT));

        for (Monitor each : monitor.monitors()) {
            ModulePanel panel = (ModulePanel) each.getPanel();
            screenshot(panel, "panel-" + panel.moduleClass());
        }
        screenshot(monitor.window(), "monitor-window-without-simulator");
    }

    @Test
    void aFailedCallIsShownAsAProblemUntilTheNextGoodReport() {
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper-Sensor");
        BumperModulePanel panel = panel(BumperModulePanel.class);
        bumperHardware.failing.set(true);
        try {
            bumper.getAllBumper();
        } catch (RuntimeException expected) {
            // the caller gets the failure; the monitor sees the error answer
        }
        eventually("the problem is shown", () -> panel.problemText().contains("bumper module does not answer"));
        bumperHardware.failing.set(false);
        bumper.getAllBumper();
        eventually("the problem is cleared", () -> panel.problemText().isEmpty());
    }

    @Test
    void aNewCallClearsTheProblemOfTheFailedOneBeforeItIsAnswered() throws Exception {
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper-Sensor");
        BumperModulePanel panel = panel(BumperModulePanel.class);
        bumperHardware.failing.set(true);
        try {
            bumper.getAllBumper();
        } catch (RuntimeException expected) {
            // the caller gets the failure; the monitor sees the error answer
        }
        eventually("the problem is shown", () -> panel.problemText().contains("bumper module does not answer"));
        String reported = onEdt(() -> panel.freshness().getText());

        // the next call is under way (the hardware holds it): what the panel says must not be the old failure
        bumperHardware.failing.set(false);
        java.util.concurrent.CountDownLatch gate = new java.util.concurrent.CountDownLatch(1);
        bumperHardware.gate.set(gate);
        Thread caller = new Thread(bumper::getAllBumper, "next call");
        caller.start();
        try {
            eventually("the problem is cleared while the call waits", () -> panel.problemText().isEmpty());
            assertTrue(caller.isAlive(), "the call is still under way");
        } finally {
            bumperHardware.gate.set(null);
            gate.countDown();
            caller.join(20_000);
        }
        eventually("its answer is shown", () -> !panel.freshness().getText().equals(reported)
                && panel.problemText().isEmpty());
    }

    @Test
    void theStatusStripCountsCallsAndErrorsAsTheyHappen() {
        MonitorWindow window = monitor.window();
        MotorModule motor = new XVSMMotorModuleRemote(laptop, ROBOT, "Motor-Controller");
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper-Sensor");
        assertEquals(0L, figure(window, "Bumper-Sensor", 5), "no errors yet");
        for (int i = 0; i < 10; i++) {
            motor.setMotor(1, i % 2 == 0 ? 0.25 : 0);
        }
        // the strip reads the statistics twice a second: wait for its next refreshes, however slow the machine
        eventually("calls per second of the motor module", () -> Double.parseDouble(
                (String) figure(window, "Motor-Controller", 3)) > 0);
        eventually("its last answer", () -> String.valueOf(figure(window, "Motor-Controller", 6))
                .startsWith("setMotor 1"));
        bumperHardware.failing.set(true);
        for (int expected = 1; expected <= 2; expected++) {
            try {
                bumper.getAllBumper();
            } catch (RuntimeException failed) {
                // counted by the strip
            }
            long errors = expected;
            eventually(errors + " error(s) counted", () -> Long.valueOf(errors).equals(figure(window,
                    "Bumper-Sensor", 5)));
        }
        assertEquals(0L, figure(window, "Motor-Controller", 5), "the motor module's calls all succeeded");
        bumperHardware.failing.set(false);
        // no more calls: the rate falls back to 0 once they are older than its window
        eventually("the rate falls to 0", Duration.ofSeconds(30), () -> Double.parseDouble(
                (String) figure(window, "Motor-Controller", 3)) == 0);
    }

    @Test
    void theStatusStripTellsAnIdleProgramFromOneThatEnded() throws Exception {
        MonitorWindow window = monitor.window();
        // nothing calls the room's modules: its program's heartbeats alone say it runs
        eventually("the idle room alive", () -> participantText(window, ROOM).equals("● DimRoom: alive"));
        assertTrue(onEdt(() -> window.statusStrip().participantLabel(ROOM).getToolTipText())
                .startsWith("heartbeats of room-pc#"));
        assertEquals(StatusStrip.ALIVE, onEdt(() -> window.statusStrip().participantLabel(ROOM).getForeground()));
        room.close(); // its last heartbeat says it ended
        eventually("the room ended", () -> participantText(window, ROOM).equals("● DimRoom: ended"));
        assertEquals("● CaterpillarRobot: alive", onEdt(() -> participantText(window, ROBOT)),
                "the robot's program runs on");
    }

    @Test
    void pausedPlotsGainNoPointsWhileValuesArriveAndShowThemOnceResumed() throws Exception {
        PlotsPanel plots = monitor.window().plots();
        ModuleRef motorModule = new ModuleRef(ROBOT, "Motor-Controller", "MotorModule");
        MotorModule motor = new XVSMMotorModuleRemote(laptop, ROBOT, "Motor-Controller");
        motor.setMotor(1, 0.25);
        eventually("the first value is plotted", () -> {
            plots.reveal(motorModule);
            plots.refresh();
            return plots.pointsShown(motorModule) >= 1;
        });
        onEdt(() -> plots.pauseButton().doClick()); // as a user does, with the mouse or Alt+U
        assertEquals("Resume plots", onEdt(() -> plots.pauseButton().getText()));
        int frozen = onEdt(() -> plots.pointsShown(motorModule));
        for (int i = 0; i < 10; i++) {
            motor.setMotor(1, i % 2 == 0 ? -0.25 : 0.25);
        }
        TimeSeries collected = monitor.plotModel().of(motorModule).channels().get(1);
        eventually("the values are still collected", () -> collected.size() >= 11);
        Thread.sleep(1_200); // two rounds of the refresh timer, which must leave a paused chart alone
        onEdt(plots::refresh);
        assertEquals(frozen, onEdt(() -> plots.pointsShown(motorModule)), "a paused plot gains no points");

        onEdt(() -> plots.pauseButton().doClick());
        assertEquals("Pause plots", onEdt(() -> plots.pauseButton().getText()));
        eventually("resumed, it shows the values that came meanwhile",
                () -> plots.pointsShown(motorModule) >= frozen + 10);
    }

    private static String participantText(MonitorWindow window, String participant) {
        window.statusStrip().refresh();
        return window.statusStrip().participantLabel(participant).getText();
    }

    /** What the status strip's table shows for {@code module} in {@code column}, read on the Swing thread. */
    private static Object figure(MonitorWindow window, String module, int column) {
        java.util.concurrent.Callable<Object> read = () -> {
            javax.swing.JTable table = window.statusStrip().table();
            for (int row = 0; row < table.getRowCount(); row++) {
                if (module.equals(table.getValueAt(row, 1))) {
                    return table.getValueAt(row, column);
                }
            }
            throw new AssertionError("no row for " + module);
        };
        try {
            return javax.swing.SwingUtilities.isEventDispatchThread() ? read.call() : onEdt(read);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void aRememberedLayoutIsRestored() throws Exception {
        Path file = folder.resolve("monitor-layout.properties");
        MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.everyModuleType(folder)));
        java.awt.Rectangle bounds = new java.awt.Rectangle(40, 30, 1100, 760);
        WorldMonitor first = onEdt(() -> new WorldMonitor(world, space.connection(), new MonitorLoader(),
                WorldMonitor.Windows.ONE, LayoutMemory.in(file)));
        try {
            onEdt(() -> {
                MonitorWindow window = first.window();
                window.setBounds(bounds);
                first.show();
                window.validate();
                window.mainSplit().setDividerLocation(520);
                window.leftSplit().setDividerLocation(310);
                window.tabs().setSelectedIndex(0);
                window.validate();
            });
            eventually("the window is shown", () -> first.window().isShowing());
            assertEquals(List.of(bounds, 520, 310), onEdt(() -> List.of(first.window().getBounds(),
                    first.window().mainSplit().getDividerLocation(), first.window().leftSplit().getDividerLocation())),
                    "the layout as set");
        } finally {
            onEdt(first::close); // closing remembers
        }
        assertTrue(java.nio.file.Files.isRegularFile(file), "the layout was written to " + file);

        WorldMonitor again = onEdt(() -> new WorldMonitor(world, space.connection(), new MonitorLoader(),
                WorldMonitor.Windows.ONE, LayoutMemory.in(file)));
        try {
            onEdt(again::show);
            MonitorWindow window = again.window();
            eventually("the window is laid out", () -> window.isShowing() && window.leftSplit().getHeight() > 0);
            assertEquals(bounds, onEdt(() -> window.getBounds()), "the same place and size");
            assertEquals(520, (int) onEdt(() -> window.mainSplit().getDividerLocation()), "the same main divider");
            assertEquals(310, (int) onEdt(() -> window.leftSplit().getDividerLocation()),
                    "the same divider between world view and plots");
            assertEquals("DimRoom", onEdt(() -> window.tabs().getTitleAt(window.tabs().getSelectedIndex())),
                    "the same tab (not the robot's, the first time's choice)");
        } finally {
            onEdt(again::close);
        }
    }

    @Test
    void aLongErrorWrapsInsideItsPanelAndEveryFieldStaysVisible() {
        MonitorWindow window = monitor.window();
        ParticipantPanel robotTab = window.participants().get(1);
        onEdt(() -> window.tabs().setSelectedComponent(robotTab));
        BumperModulePanel panel = panel(BumperModulePanel.class);
        java.awt.Dimension windowSize = onEdt(() -> window.getSize());
        java.awt.Rectangle panelBounds = onEdt(() -> panel.getBounds());
        int columnWidth = onEdt(() -> robotTab.column().getWidth());
        int preferredWidth = onEdt(() -> panel.getPreferredSize().width);

        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper-Sensor");
        bumperHardware.message.set("the bumper module at address 2 did not answer: " + "no reply within 100 ms, "
                .repeat(20) + "check the cable, the module's power and its address");
        bumperHardware.failing.set(true);
        try {
            bumper.getAllBumper();
        } catch (RuntimeException expected) {
            // the monitor shows the error answer
        }
        eventually("the long problem is shown", () -> panel.problemText().contains("check the cable"));
        onEdt(() -> {
            window.validate();
            return null;
        });
        assertEquals(windowSize, onEdt(() -> window.getSize()), "the window keeps its size");
        assertEquals(panelBounds, onEdt(() -> panel.getBounds()), "the panel keeps its place and size");
        assertEquals(columnWidth, onEdt(() -> robotTab.column().getWidth()), "nothing scrolls sideways");
        assertEquals(preferredWidth, onEdt(() -> panel.getPreferredSize().width),
                "the message does not make the panel want more width (which would widen a packed window)");
        List<String> outside = onEdt(() -> {
            List<String> found = new java.util.ArrayList<>();
            collectOutside(robotTab.column(), robotTab.column(), found);
            return found;
        });
        assertTrue(outside.isEmpty(), "every field lies within the tab's width: " + outside);
        java.awt.Rectangle problem = onEdt(() -> javax.swing.SwingUtilities.convertRectangle(
                panel.problemArea().getParent(), panel.problemArea().getBounds(), panel));
        assertTrue(problem.x >= 0 && problem.x + problem.width <= panelBounds.width, "the message wraps inside: "
                + problem);
        screenshot(window, "monitor-window-long-error");
        bumperHardware.failing.set(false);
        bumper.getAllBumper();
        eventually("the problem is cleared", () -> panel.problemText().isEmpty());
    }

    /** Visible components sticking out of {@code root} to the left or right. */
    private static void collectOutside(java.awt.Container root, java.awt.Container container, List<String> found) {
        for (java.awt.Component child : container.getComponents()) {
            if (!child.isVisible()) {
                continue;
            }
            java.awt.Rectangle bounds = javax.swing.SwingUtilities.convertRectangle(container, child.getBounds(), root);
            if (bounds.x < 0 || bounds.x + bounds.width > root.getWidth()) {
                found.add(child.getClass().getSimpleName() + " " + child.getName() + " " + bounds);
            }
            if (child instanceof java.awt.Container inner) {
                collectOutside(root, inner, found);
            }
        }
    }

    @Test
    void localCallsOnTheModulesHostAreShownToo() {
        XVSMX10ApplianceModuleLocal local = new XVSMX10ApplianceModuleLocal(room, ROOM, "Lamp",
                new FakeHardware.Appliance());
        X10ApplianceModulePanel panel = panel(X10ApplianceModulePanel.class);
        local.on();
        eventually("the published local call is shown", () -> panel.indicator().state() == OnOffIndicator.State.ON);
        assertTrue(onEdt(() -> panel.freshness().getText()).contains("for room-pc"));
    }

    @Test
    void aMonitorStartedLaterShowsTheLastKnownState() throws Exception {
        XVSMX10ApplianceModuleLocal local = new XVSMX10ApplianceModuleLocal(room, ROOM, "Lamp",
                new FakeHardware.Appliance());
        local.on();
        X10ApplianceModulePanel first = panel(X10ApplianceModulePanel.class);
        eventually("published", () -> first.indicator().state() == OnOffIndicator.State.ON);

        MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.everyModuleType(folder)));
        WorldMonitor late = onEdt(() -> new WorldMonitor(world, space.connection(), new MonitorLoader()));
        try {
            assertTrue(late.awaitWatching(Duration.ofSeconds(10)));
            X10ApplianceModulePanel panel = panel(late, X10ApplianceModulePanel.class);
            eventually("the late monitor shows ON", () -> panel.indicator().state() == OnOffIndicator.State.ON);
            assertEquals("reported before monitoring started for room-pc", onEdt(() -> panel.freshness().getText()));
            assertEquals(FreshnessLabel.NO_REPORT, onEdt(() -> panel(late, BumperModulePanel.class).freshness()
                    .getText()), "nothing was published for the bumper");
        } finally {
            onEdt(late::close);
        }
    }

    @Test
    void aMonitorThatCannotWatchSaysSoOnItsPanelAndTheWindowStaysResponsive() throws Exception {
        MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.everyModuleType(folder)));
        Capi closed = MonitorSpace.open(space.url());
        closed.close(); // every operation on it fails at once
        WorldMonitor broken = onEdt(() -> new WorldMonitor(world, closed, new MonitorLoader()));
        try {
            assertFalse(broken.awaitWatching(Duration.ofSeconds(10)));
            BumperModulePanel panel = panel(broken, BumperModulePanel.class);
            eventually("the panel says why", () -> panel.problemText().startsWith("not watching: cannot watch ")
                    && panel.problemText().contains("Bumper-Sensor"));
        } finally {
            onEdt(broken::close);
        }
    }

    private <P> P panel(Class<P> type) {
        return panel(monitor, type);
    }

    private static <P> P panel(WorldMonitor monitor, Class<P> type) {
        return monitor.monitors().stream().map(Monitor::getPanel).filter(type::isInstance).map(type::cast)
                .findFirst().orElseThrow();
    }
}
