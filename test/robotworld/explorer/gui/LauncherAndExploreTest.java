package robotworld.explorer.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.eventually;
import static robotworld.explorer.gui.GuiTesting.onEdt;
import static robotworld.explorer.gui.GuiTesting.screenshot;

import java.awt.Component;
import java.awt.Container;
import java.awt.Frame;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import javax.swing.AbstractButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.explorer.RobotWorldExplorer;
import robotworld.explorer.frames.AssembleFrame;
import robotworld.explorer.frames.ExploreFrame;
import robotworld.explorer.frames.GenerateFrame;
import robotworld.explorer.frames.MonitorFrame;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;

/** The launcher and its four windows: titles, keyboard access, and a real bus exploration. */
class LauncherAndExploreTest {

    private static final String ROBOT = """
            <SimulatedRobot name="GuiBot">
              <World width="2000" height="1000"/>
              <Body x="500" y="500"/>
              <Motor address="1" left="1" right="2"/>
              <Bumper address="2"/>
            </SimulatedRobot>""";

    @TempDir
    Path temp;

    private final List<JFrame> opened = new ArrayList<>();

    @BeforeEach
    void needsADisplay() {
        GuiTesting.assumeDisplay();
    }

    @AfterEach
    void closeAll() {
        onEdt(() -> {
            for (Frame frame : Frame.getFrames()) {
                frame.dispose();
            }
        });
    }

    @Test
    void theLauncherOpensEachWindowAndEverythingHasAKey() {
        RobotWorldExplorer launcher = show(() -> new RobotWorldExplorer(ProjectFiles.root()));
        assertEquals("RobotWorldExplorer", launcher.getTitle());
        assertEquals(List.of('E', 'A', 'G', 'M'), onEdt(() -> List.of((char) launcher.exploreButton().getMnemonic(),
                (char) launcher.assembleButton().getMnemonic(), (char) launcher.generateButton().getMnemonic(),
                (char) launcher.monitorButton().getMnemonic())));
        screenshot(launcher, "launcher");

        onEdt(() -> {
            launcher.exploreButton().doClick();
            launcher.assembleButton().doClick();
            launcher.generateButton().doClick();
            launcher.monitorButton().doClick();
        });
        List<String> titles = onEdt(() -> Arrays.stream(Frame.getFrames()).filter(Frame::isVisible)
                .map(Frame::getTitle).toList());
        assertTrue(titles.containsAll(List.of(ExploreFrame.TITLE, AssembleFrame.TITLE, GenerateFrame.TITLE,
                MonitorFrame.TITLE)), titles.toString());
        for (Frame frame : onEdt(Frame::getFrames)) {
            if (frame.isVisible()) {
                assertEveryControlHasAKey((JFrame) frame);
            }
        }
        MonitorFrame monitor = (MonitorFrame) onEdt(() -> Arrays.stream(Frame.getFrames())
                .filter(MonitorFrame.class::isInstance).findFirst().orElseThrow());
        screenshot(monitor, "monitor-frame");
    }

    @Test
    void exploresASimulatedRobotAndWritesItsDescription() throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.parse(ROBOT, "gui robot"))) {
            String port = robot.serve("tcp://127.0.0.1:0");
            ExploreFrame frame = show(() -> new ExploreFrame(ProjectFiles.root()));
            screenshot(frame, "explore-frame");
            onEdt(() -> {
                frame.portField().getEditor().setItem(port);
                frame.robotNameField().setText("GuiBot");
                frame.destinationField().setText(temp.toString());
                frame.exploreButton().doClick();
            });
            // about 3 s on a quiet machine; only a failure waits the whole minute
            eventually("the exploration ends", Duration.ofSeconds(60), () -> frame.exploreButton().isEnabled());
            assertTrue(onEdt(frame::statusText).startsWith("wrote "), onEdt(frame::statusText) + "\n"
                    + onEdt(frame::logText));
            assertTrue(Files.readString(temp.resolve("GuiBot.xml")).contains("<RobotName>GuiBot</RobotName>"));
            assertEquals(247, onEdt(() -> frame.progress().getValue()));
            assertTrue(onEdt(frame::logText).contains("found"), onEdt(frame::logText));
            screenshot(frame, "explore-frame-done");
        }
    }

    @Test
    void aPortThatDoesNotExistIsAnErrorInTheWindow() {
        ExploreFrame frame = show(() -> new ExploreFrame(ProjectFiles.root()));
        onEdt(() -> {
            frame.portField().getEditor().setItem("tcp://127.0.0.1:1");
            frame.destinationField().setText(temp.toString());
            frame.exploreButton().doClick();
        });
        eventually("the error is shown", Duration.ofSeconds(15), () -> frame.exploreButton().isEnabled());
        assertTrue(onEdt(frame::logText).contains("error: "), onEdt(frame::logText));
        assertEquals("failed", onEdt(() -> frame.progress().getString()));
        String first = onEdt(frame::logText);

        // a new exploration starts with an empty log: the last one's error is not taken for this one's
        String atStart = onEdt(() -> {
            frame.portField().getEditor().setItem("tcp://127.0.0.1:2");
            frame.exploreButton().doClick();
            return frame.logText();
        });
        assertEquals("", atStart);
        eventually("the second error is shown", Duration.ofSeconds(15), () -> frame.exploreButton().isEnabled());
        String second = onEdt(frame::logText);
        assertEquals(1, second.split("error: ", -1).length - 1, second);
        assertFalse(second.contains(first.strip()), second);
    }

    private <F extends JFrame> F show(java.util.concurrent.Callable<F> create) {
        F frame = onEdt(() -> {
            F created = create.call();
            created.setVisible(true);
            return created;
        });
        opened.add(frame);
        return frame;
    }

    /** Every enabled button has a mnemonic, every label that names a field points at it with one. */
    private static void assertEveryControlHasAKey(JFrame frame) {
        onEdt(() -> check(frame.getContentPane(), frame.getTitle()));
    }

    private static void check(Component component, String window) {
        if (component instanceof AbstractButton button && !(button instanceof javax.swing.JRadioButton)
                && button.isEnabled() && !button.getText().isEmpty() && !(component.getParent() instanceof javax.swing.JComboBox)) {
            assertTrue(button.getMnemonic() != 0, window + ": button '" + button.getText() + "' has no mnemonic");
        }
        if (component instanceof JLabel label && label.getLabelFor() != null) {
            assertTrue(label.getDisplayedMnemonic() != 0, window + ": label '" + label.getText() + "' has no mnemonic");
        }
        if (component instanceof Container container) {
            for (Component child : container.getComponents()) {
                check(child, window);
            }
        }
    }
}
