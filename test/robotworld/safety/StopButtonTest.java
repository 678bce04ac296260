package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.onEdt;
import static robotworld.explorer.gui.GuiTesting.screenshot;

import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.RobotWorldExplorer;
import robotworld.explorer.frames.MonitorFrame;
import robotworld.explorer.gui.GuiTesting;
import robotworld.explorer.monitor.MonitorLoader;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldMonitor;
import robotworld.explorer.stop.StopButton;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.x10.CM11aController;
import robotworld.x10.X10LampModuleLocal;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMX10LampModuleLocal;

/** Rule 5 from the windows: the STOP button of every monitor window, of the monitor frame and of the launcher. */
class StopButtonTest {

    @TempDir
    Path temp;

    private SafetyRig rig;
    private XVSMRuntime robot;
    private XVSMRuntime room;
    private XVSMMotorModuleLocal motor;
    private MonitoredWorld world;
    private Path worldFile;

    @BeforeEach
    void start() throws Exception {
        GuiTesting.assumeDisplay();
        rig = SafetyRig.start();
        worldFile = rig.writeWorld(temp.resolve("safety-world.xml"));
        world = MonitoredWorld.of(DescriptionLoader.loadWorld(worldFile, DescriptionSchemas.configured()));
        robot = XVSMRuntime.connect(rig.spaceUrl, "robot-pc");
        SafetyRig.relax(robot);
        RS485Bus bus = robot.own(new RS485Bus(rig.busPort, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO)));
        motor = robot.own(new XVSMMotorModuleLocal(robot, SafetyRig.ROBOT, SafetyRig.MOTOR,
                new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
        robot.own(new XVSMBumperModuleLocal(robot, SafetyRig.ROBOT, SafetyRig.BUMPER,
                new BumperModuleProxy(bus, 2, SafetyRig.BUMPER)));
        room = XVSMRuntime.connect(rig.spaceUrl, "room-pc");
        CM11aController x10 = room.own(CM11aController.open(rig.x10Port));
        room.own(new XVSMX10LampModuleLocal(room, SafetyRig.ROOM, SafetyRig.LAMP, new X10LampModuleLocal(x10, 'A', 1)));
    }

    @AfterEach
    void stop() {
        if (rig != null) {
            robot.close();
            room.close();
            rig.close();
        }
    }

    @Test
    void theMonitorWindowHasAStopButtonThatStopsTheWorld() throws Exception {
        try (Capi space = RemoteSpace.open(rig.space.uri())) {
            WorldMonitor monitor = onEdt(() -> {
                WorldMonitor opened = new WorldMonitor(world, space, new MonitorLoader());
                opened.show();
                return opened;
            });
            try {
                assertEquals(1, monitor.stopButtons().size(), "one in the monitor window");
                assertTrue(onEdt(() -> monitor.stopButtons().get(0).isShowing()), "at the top of the window");
                WorldMonitor perParticipant = onEdt(() -> new WorldMonitor(world, space, new MonitorLoader(),
                        WorldMonitor.Windows.PER_PARTICIPANT, robotworld.explorer.monitor.gui.LayoutMemory.none()));
                assertEquals(2, perParticipant.stopButtons().size(), "one per participant's window");
                onEdt(perParticipant::close);
                motor.setMotor(1, 0.6);
                StopButton button = monitor.stopButtons().get(0);
                javax.swing.JFrame window = monitor.window();
                onEdt(() -> button.button().doClick());
                clickedAndEveryActuatorStopped(button);
                robotworld.explorer.monitor.gui.MotorModulePanel panel =
                        (robotworld.explorer.monitor.gui.MotorModulePanel) monitor.monitors().get(1).getPanel();
                GuiTesting.eventually("the motor panel says why it stopped", Duration.ofSeconds(30),
                        () -> panel.stoppedText().contains("(stop-request: asked by "));
                assertTrue(onEdt(panel::stoppedText).contains("motors 1-8 set to 0"), onEdt(panel::stoppedText));
                screenshot(window, "monitor-window-after-stop");
                org.junit.jupiter.api.Assertions.assertThrows(robotworld.xvsm.ActuatorStoppedException.class,
                        () -> motor.setMotor(1, 0.2), "the program serving it is told first");
                motor.setMotor(1, 0.2);
                GuiTesting.eventually("commanded again, the stop line goes", Duration.ofSeconds(30),
                        () -> panel.stoppedText().isEmpty());
            } finally {
                onEdt(monitor::close);
            }
        }
    }

    @Test
    void theLauncherStopsTheWorldItWasGiven() throws Exception {
        RobotWorldExplorer launcher = onEdt(() -> {
            RobotWorldExplorer opened = new RobotWorldExplorer(temp);
            opened.setWorldToStop(world, rig.spaceUrl);
            opened.setVisible(true);
            return opened;
        });
        try {
            motor.setMotor(2, -0.6);
            onEdt(() -> launcher.stopButton().button().doClick());
            clickedAndEveryActuatorStopped(launcher.stopButton());
            screenshot(launcher, "launcher-after-stop");
        } finally {
            onEdt(launcher::dispose);
        }
    }

    @Test
    void theMonitorFrameStopsTheWorldInItsFields() throws Exception {
        MonitorFrame frame = onEdt(() -> {
            MonitorFrame opened = new MonitorFrame();
            opened.worldFileField().setText(worldFile.toString());
            opened.setVisible(true);
            return opened;
        });
        try {
            motor.setMotor(1, 0.3);
            onEdt(() -> frame.stopButton().button().doClick());
            clickedAndEveryActuatorStopped(frame.stopButton());
        } finally {
            onEdt(frame::dispose);
        }
    }

    @Test
    void aStopThatMissesAnActuatorSaysSoInRed() throws Exception {
        room.close();
        RobotWorldExplorer launcher = onEdt(() -> {
            RobotWorldExplorer opened = new RobotWorldExplorer(temp);
            opened.setWorldToStop(world, rig.spaceUrl);
            return opened;
        });
        try {
            motor.setMotor(1, 0.3);
            onEdt(() -> launcher.stopButton().button().doClick());
            GuiTesting.eventually("the outcome", Duration.ofSeconds(30),
                    () -> launcher.stopButton().lastResult() != null);
            assertTrue(rig.motorsStopped());
            String text = onEdt(() -> launcher.stopButton().outcomeText());
            assertTrue(text.equals("NOT confirmed stopped: SafetyRoom/Lamp"), text);
        } finally {
            onEdt(launcher::dispose);
        }
    }

    private void clickedAndEveryActuatorStopped(StopButton button) {
        GuiTesting.eventually("the outcome", Duration.ofSeconds(30), () -> button.lastResult() != null
                || button.lastProblem() != null);
        assertEquals(null, button.lastProblem());
        assertTrue(rig.motorsStopped());
        String text = onEdt(button::outcomeText);
        assertTrue(text.startsWith("all 2 actuator(s) stopped ("), text);
    }
}
