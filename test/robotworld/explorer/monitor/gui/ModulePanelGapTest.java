package robotworld.explorer.monitor.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;

import org.junit.jupiter.api.Test;

/** A module panel keeps showing that notifications were missed, and how often. */
class ModulePanelGapTest {

    @Test
    void missedNotificationsStayVisibleWithACount() throws Exception {
        javax.swing.SwingUtilities.invokeAndWait(() -> {
            PlaceholderPanel panel = new PlaceholderPanel("MotorModule", "motor", "XVSMMotorModuleMonitor", "test");
            assertEquals("", panel.gapText());
            panel.showGap(Instant.now(), "the space dropped notifications; watching again");
            assertTrue(panel.gapText().startsWith("notifications missed at "), panel.gapText());
            panel.clearProblem(); // a good answer does not hide it
            panel.showGap(Instant.now(), "again");
            assertTrue(panel.gapText().startsWith("notifications missed 2x, last at "), panel.gapText());
        });
    }
}
