package robotworld.explorer.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.onEdt;
import static robotworld.explorer.gui.GuiTesting.screenshot;

import java.awt.Frame;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.description.DescriptionLoader;
import robotworld.description.EnvModuleListType;
import robotworld.description.RobotWorldType;
import robotworld.explorer.frames.AssembleFrame;
import robotworld.explorer.frames.GenerateFrame;
import robotworld.testsupport.ProjectFiles;

/** "Assemble a world", driven as a user would: robot files, a device table, a name, Save; then on to Generate. */
class AssembleFrameTest {

    private static final Path ROBOT = ProjectFiles.resolve("docs/examples/parts/caterpillar-robot.xml");

    @TempDir
    Path temp;

    private AssembleFrame frame;

    @BeforeEach
    void open() {
        GuiTesting.assumeDisplay();
        frame = onEdt(() -> {
            AssembleFrame opened = new AssembleFrame(temp);
            opened.setVisible(true);
            return opened;
        });
    }

    @AfterEach
    void close() {
        onEdt(() -> Arrays.stream(Frame.getFrames())
                .filter(f -> f instanceof AssembleFrame || f instanceof GenerateFrame).forEach(Frame::dispose));
    }

    @Test
    void savesAWorldMadeOfARobotAndATableOfX10Devices() throws Exception {
        Path world = temp.resolve("Lab.xml");
        onEdt(() -> {
            frame.worldNameField().setText("Lab");
            frame.addRobotFile(ROBOT);
            frame.environmentNameField().setText("DimRoom");
            frame.environmentHostField().setText("room-pc");
            frame.cm11aPortField().setText("tcp://127.0.0.1:5030");
            frame.addDeviceRow("A3", "appliance", "Lamp");
            frame.addDeviceRow("B1", "lamp", "");
            frame.outputField().setText(world.toString());
        });
        screenshot(frame, "assemble-frame-filled");
        onEdt(() -> frame.saveButton().doClick());
        assertTrue(onEdt(frame::statusText).startsWith("Saved " + world), onEdt(frame::statusText));
        RobotWorldType loaded = DescriptionLoader.loadWorld(world).getRobotWorld();
        EnvModuleListType room = loaded.getEnvironmentArray(0);
        assertEquals("DimRoom", room.getEnvironmentName());
        assertEquals("tcp://127.0.0.1:5030", room.getCOMPort());
        assertEquals(2, room.sizeOfX10ModuleArray());
        assertEquals("Lamp-B1", room.getX10ModuleArray(1).getName(), "a blank name is the kind's, made unique");
        assertEquals("CaterpillarRobot", loaded.getRobotDescriptionArray(0).getRobotName());
        screenshot(frame, "assemble-frame-saved");

        assertTrue(onEdt(() -> frame.generateButton().isEnabled()), "the next step is one click away");
        onEdt(() -> frame.generateButton().doClick());
        GenerateFrame next = onEdt(() -> (GenerateFrame) Arrays.stream(Frame.getFrames())
                .filter(f -> f instanceof GenerateFrame && f.isVisible()).findFirst().orElseThrow());
        assertEquals(3, onEdt(() -> next.viewpointButtons().size()), "DimRoom, CaterpillarRobot, external");
    }

    @Test
    void problemsAreListedAndNothingIsSaved() throws Exception {
        Path world = temp.resolve("Twice.xml");
        Path copy = Files.copy(ROBOT, temp.resolve("copy.xml"));
        onEdt(() -> {
            frame.worldNameField().setText("Twice");
            frame.addRobotFile(ROBOT);
            frame.addRobotFile(copy);
            frame.outputField().setText(world.toString());
            frame.saveButton().doClick();
        });
        assertTrue(onEdt(frame::errorsText).startsWith(copy + ":4:13: duplicate participant name 'CaterpillarRobot'"),
                onEdt(frame::errorsText));
        assertTrue(onEdt(frame::statusText).contains("nothing was saved"));
        assertFalse(Files.exists(world));
        screenshot(frame, "assemble-frame-errors");

        onEdt(() -> {
            frame.addDeviceRow("Q9", "lamp", "");
            frame.saveButton().doClick();
        });
        assertEquals("Device in row 1: the house code is a letter from A to P; got 'Q'", onEdt(frame::statusText));
        assertFalse(onEdt(() -> frame.generateButton().isEnabled()));
    }
}
