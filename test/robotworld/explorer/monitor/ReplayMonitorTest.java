package robotworld.explorer.monitor;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.eventually;
import static robotworld.explorer.gui.GuiTesting.onEdt;
import static robotworld.explorer.gui.GuiTesting.screenshot;

import java.awt.Component;
import java.awt.Container;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JFrame;
import javax.swing.JLabel;
import org.junit.jupiter.api.Test;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.gui.GuiTesting;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.observe.ReplayMark;
import robotworld.space.EmbeddedSpace;
import robotworld.testsupport.ProjectFiles;

/** The monitor windows and the console monitor say when the space they watch replays a recording. */
class ReplayMonitorTest {

    private static final ReplayMark MARK = new ReplayMark("run.mcap", Instant.parse("2026-11-23T10:00:00Z"), 1);

    private static MonitoredWorld world() throws Exception {
        return MonitoredWorld.of(DescriptionLoader.loadWorld(ProjectFiles.resolve("docs/examples/chapter5-world.xml")));
    }

    @Test
    void theConsoleMonitorSaysItFirst() throws Exception {
        StringWriter text = new StringWriter();
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            MARK.publish(space);
            new ConsoleMonitor(world(), space, new PrintWriter(text, true)).close();
        }
        assertTrue(text.toString().startsWith("# REPLAY of run.mcap (recorded "), text.toString());
    }

    @Test
    void everyWindowShowsABannerAndSaysItInItsTitle() throws Exception {
        GuiTesting.assumeDisplay();
        MonitoredWorld world = world();
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            MARK.publish(space);
            for (WorldMonitor.Windows layout : WorldMonitor.Windows.values()) {
                WorldMonitor monitor = onEdt(() -> new WorldMonitor(world, space, new MonitorLoader(), layout,
                        LayoutMemory.none()));
                try {
                    onEdt(monitor::show);
                    List<JFrame> frames = new ArrayList<>(monitor.windows());
                    if (monitor.window() != null) {
                        frames.add(monitor.window());
                    }
                    assertTrue(!frames.isEmpty());
                    for (JFrame window : frames) {
                        eventually("a replay banner in " + window.getTitle(), () ->
                                window.getTitle().startsWith("REPLAY of run.mcap") && banner(window) != null);
                        assertTrue(onEdt(() -> banner(window).getText()).contains("nothing is driven"));
                    }
                    screenshot(frames.get(frames.size() - 1), "monitor-replay-" + layout.name().toLowerCase());
                } finally {
                    onEdt(monitor::close);
                }
            }
        }
    }

    private static JLabel banner(Container container) {
        for (Component child : container.getComponents()) {
            if (child instanceof JLabel label && "replay-banner".equals(label.getName())) {
                return label;
            }
            if (child instanceof Container inner) {
                JLabel found = banner(inner);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }
}
