package robotworld.explorer.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.eventually;
import static robotworld.explorer.gui.GuiTesting.onEdt;
import static robotworld.explorer.gui.GuiTesting.screenshot;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import javax.swing.JRadioButton;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.explorer.frames.GenerateFrame;
import robotworld.testsupport.ProjectFiles;

/** The generate frame, driven as a user would: load, choose, Generate, read the result. */
class GenerateFrameTest {

    @TempDir
    Path temp;

    private GenerateFrame frame;

    @BeforeEach
    void open() {
        GuiTesting.assumeDisplay();
        frame = onEdt(() -> {
            GenerateFrame opened = new GenerateFrame();
            opened.setVisible(true);
            return opened;
        });
    }

    @AfterEach
    void close() {
        if (frame != null) {
            onEdt(frame::dispose);
        }
    }

    @Test
    void generatesTheProjectOfTheChosenViewpoint() {
        Path destination = temp.resolve("DimRoomProject");
        onEdt(() -> {
            frame.worldFileField().setText(ProjectFiles.resolve("docs/examples/chapter5-world.xml").toString());
            frame.loadButton().doClick();
        });
        List<String> viewpoints = onEdt(() -> frame.viewpointButtons().stream().map(JRadioButton::getActionCommand)
                .toList());
        assertEquals(List.of("DimRoom", "CaterpillarRobot", "external"), viewpoints);
        assertEquals("chapter5", onEdt(() -> frame.packageNameField().getText()));
        assertEquals(6, onEdt(() -> frame.tree().getRowCount()), "world, 2 participants, 3 modules, expanded");
        screenshot(frame, "generate-frame-loaded");

        onEdt(() -> {
            frame.viewpointButtons().get(0).setSelected(true);
            frame.destinationField().setText(destination.toString());
            frame.generateButton().doClick();
        });
        eventually("the result is shown", Duration.ofSeconds(20), () -> !frame.resultText().isEmpty()
                || frame.statusText().contains("failed"));
        assertEquals(destination.toAbsolutePath().normalize().toString(), onEdt(frame::resultText),
                onEdt(frame::statusText));
        assertTrue(Files.isRegularFile(destination.resolve("build.xml")));
        assertTrue(Files.isRegularFile(destination.resolve("src/chapter5/DimRoom.java")));
        assertTrue(onEdt(frame::statusText).contains("main class chapter5."), onEdt(frame::statusText));
        screenshot(frame, "generate-frame-done");

        // another world loaded: the project generated from the one before is no longer this window's result
        onEdt(() -> {
            frame.worldFileField().setText(ProjectFiles.resolve("docs/examples/lab-world.xml").toString());
            frame.loadButton().doClick();
        });
        assertEquals("", onEdt(frame::resultText), "the last generation's result is cleared");
        assertEquals("", onEdt(frame::progressText));
        assertTrue(onEdt(frame::statusText).startsWith("Loaded "), onEdt(frame::statusText));
    }

    @Test
    void validationErrorsAreListedWithLineAndColumn() throws Exception {
        String broken = Files.readString(ProjectFiles.resolve("docs/examples/chapter5-world.xml"))
                .replace("<UnitCode>THREE</UnitCode>", "<UnitCode>SEVENTEEN</UnitCode>");
        Path world = Files.writeString(temp.resolve("broken-world.xml"), broken);
        onEdt(() -> {
            frame.worldFileField().setText(world.toString());
            frame.loadButton().doClick();
        });
        String errors = onEdt(frame::errorsText);
        assertTrue(errors.matches("(?s).*broken-world\\.xml:\\d+:\\d+: .*SEVENTEEN.*"), errors);
        assertFalse(onEdt(() -> frame.generateButton().isEnabled()));
        assertTrue(onEdt(frame::statusText).contains("problem"));
        screenshot(frame, "generate-frame-errors");
    }

    @Test
    void aFailedGenerationIsShownNotThrown() throws Exception {
        Path occupied = Files.createDirectories(temp.resolve("occupied"));
        Files.writeString(occupied.resolve("notes.txt"), "mine");
        onEdt(() -> {
            frame.worldFileField().setText(ProjectFiles.resolve("docs/examples/chapter5-world.xml").toString());
            frame.loadButton().doClick();
            frame.destinationField().setText(occupied.toString());
            frame.generateButton().doClick();
        });
        eventually("the failure is shown", Duration.ofSeconds(20), () -> frame.generateButton().isEnabled()
                && !frame.statusText().startsWith("Generating"));
        assertEquals("", onEdt(frame::resultText));
        assertTrue(Files.exists(occupied.resolve("notes.txt")));
        assertEquals("failed", onEdt(frame::progressText));

        // the next generation starts clean: neither "failed" nor the error stays while it runs
        Path free = temp.resolve("free");
        List<String> atStart = onEdt(() -> {
            frame.destinationField().setText(free.toString());
            frame.generateButton().doClick();
            return List.of(frame.progressText(), frame.statusText(), frame.resultText());
        });
        assertEquals(List.of("starting", "Generating...", ""), atStart);
        eventually("the project is generated", Duration.ofSeconds(20), () -> !frame.resultText().isEmpty());
        assertEquals("done", onEdt(frame::progressText));
    }
}
