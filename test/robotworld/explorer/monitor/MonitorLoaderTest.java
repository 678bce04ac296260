package robotworld.explorer.monitor;

import java.time.Duration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.eventually;
import static robotworld.explorer.gui.GuiTesting.onEdt;

import java.awt.GraphicsEnvironment;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import robotworld.core.GripperModule;
import robotworld.explorer.gui.GuiTesting;
import robotworld.explorer.monitor.gui.ParticipantWindow;
import robotworld.explorer.monitor.gui.PlaceholderPanel;
import robotworld.explorer.monitor.logic.xvsm.XVSMGripperModuleMonitor;
import robotworld.space.EmbeddedSpace;
import robotworld.xvsm.XVSMGripperModuleLocal;
import robotworld.xvsm.XVSMGripperModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * Monitors are found by name: a module type that exists only in the test sources brings its own monitor and is
 * monitored without any change to existing code; a missing monitor class gives a placeholder, not a crash.
 */
class MonitorLoaderTest {

    private final MonitorLoader loader = new MonitorLoader();

    @Test
    void theNamingConventionGivesTheClassName() {
        assertEquals("robotworld.explorer.monitor.logic.xvsm.XVSMBumperModuleMonitor",
                new MonitoredModule("xvsm", "Robot", "Bumper", "BumperModule", null).monitorClassName());
    }

    @Test
    void aMonitorThatExistsOnlyInTestSourcesIsLoadedAndWatchesTheSpace() throws Exception {
        AtomicInteger force = new AtomicInteger();
        GripperModule hardware = new GripperModule() {
            @Override
            public void grip(int newForce) {
                force.set(newForce);
            }

            @Override
            public int force() {
                return force.get();
            }
        };
        try (EmbeddedSpace space = EmbeddedSpace.open();
             XVSMRuntime robot = XVSMRuntime.using(space, "robot-laptop");
             XVSMRuntime laptop = XVSMRuntime.using(space, "laptop")) {
            MonitoredModule gripper = new MonitoredModule("xvsm", "CaterpillarRobot", "Gripper", "GripperModule", null);
            Monitor monitor = onEdt(() -> loader.load(gripper, space));
            try {
                assertInstanceOf(XVSMGripperModuleMonitor.class, monitor);
                assertTrue(monitor.awaitWatching(Duration.ofSeconds(10)), "the monitor watches");
                robot.own(new XVSMGripperModuleLocal(robot, "CaterpillarRobot", "Gripper", hardware));
                laptop.own(new XVSMGripperModuleRemote(laptop, "CaterpillarRobot", "Gripper")).grip(70);
                XVSMGripperModuleMonitor.GripperPanel panel = (XVSMGripperModuleMonitor.GripperPanel) monitor.getPanel();
                eventually("the gripper's force is shown", () -> panel.forceText().equals("70 %"));
            } finally {
                monitor.close();
            }
        }
    }

    @Test
    void aMissingMonitorClassGivesAPlaceholderNamingIt() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            MonitoredModule teleporter = new MonitoredModule("xvsm", "CaterpillarRobot", "Beam", "TeleporterModule",
                    null);
            Monitor monitor = onEdt(() -> loader.load(teleporter, space));
            MissingMonitor missing = assertInstanceOf(MissingMonitor.class, monitor);
            assertEquals("robotworld.explorer.monitor.logic.xvsm.XVSMTeleporterModuleMonitor", missing.className());
            PlaceholderPanel panel = assertInstanceOf(PlaceholderPanel.class, monitor.getPanel());
            assertTrue(panel.message().contains("robotworld.explorer.monitor.logic.xvsm.XVSMTeleporterModuleMonitor"),
                    panel.message());
            if (!GraphicsEnvironment.isHeadless()) {
                ParticipantWindow window = onEdt(() -> new ParticipantWindow("Chapter5World", "CaterpillarRobot",
                        "robot", List.of(panel)));
                try {
                    onEdt(() -> window.setVisible(true));
                    GuiTesting.screenshot(panel, "panel-placeholder");
                } finally {
                    onEdt(window::dispose);
                }
            }
        }
    }

    @Test
    void aCommunicationTypeWithoutMonitorsGivesPlaceholdersToo() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            Monitor monitor = onEdt(() -> loader.load(
                    new MonitoredModule("corba", "Robot", "Bumper", "BumperModule", null), space));
            assertEquals("robotworld.explorer.monitor.logic.corba.CORBABumperModuleMonitor",
                    ((MissingMonitor) monitor).className());
        }
    }

    @Test
    void aMonitorClassThatIsNotAMonitorIsReportedNotUsed() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            // robotworld.explorer.monitor.logic.xvsm.XVSMMonitor exists but has the wrong shape for "" + Monitor
            Monitor monitor = onEdt(() -> loader.load(new MonitoredModule("xvsm", "Robot", "X", "", null), space));
            assertTrue(((MissingMonitor) monitor).reason().contains("constructor"),
                    ((MissingMonitor) monitor).reason());
        }
    }
}
