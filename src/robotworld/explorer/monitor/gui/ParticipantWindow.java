package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.WindowConstants;

/**
 * One participant's monitoring window (thesis 4.2.4; {@code rwe monitor --window-per-participant}): the panels of
 * its modules one below the other, titled "Monitor: &lt;participant&gt; (robot) - &lt;world&gt;". It opens at least
 * {@value #MIN_WIDTH} × {@value #MIN_HEIGHT} pixels, so a participant with one small module is not a clipped sliver.
 */
public class ParticipantWindow extends JFrame {

    static final int MIN_WIDTH = 460;
    static final int MIN_HEIGHT = 260;

    /**
     * @param world       the world's name
     * @param participant the robot's or environment's name
     * @param kind        {@code robot} or {@code environment}
     * @param panels      the module panels, in description order
     */
    public ParticipantWindow(String world, String participant, String kind, List<JComponent> panels) {
        super(title(world, participant, kind));
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        getContentPane().add(new ParticipantPanel(participant, kind, panels), BorderLayout.CENTER);
        pack();
        setMinimumSize(new Dimension(MIN_WIDTH, MIN_HEIGHT));
        setSize(Math.max(MIN_WIDTH, getWidth()), Math.max(MIN_HEIGHT, Math.min(getHeight(), 900)));
    }

    /**
     * Shows a bar at the top of the window, outside the scrolled panels, so it is always visible: the STOP button
     * of the world.
     */
    public void showAtTop(JComponent bar) {
        getContentPane().add(bar, BorderLayout.NORTH);
        pack();
        setSize(Math.max(MIN_WIDTH, getWidth()), Math.max(MIN_HEIGHT, Math.min(getHeight(), 900)));
    }

    /** The window title for a participant. */
    public static String title(String world, String participant, String kind) {
        return "Monitor: " + participant + " (" + kind + ") - " + world;
    }
}
