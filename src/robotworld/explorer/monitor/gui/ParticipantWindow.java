package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.WindowConstants;

/**
 * One participant's monitoring window (thesis 4.2.4): the panels of its modules one below the other, titled
 * "Monitor: &lt;participant&gt; (robot) - &lt;world&gt;".
 */
public class ParticipantWindow extends JFrame {

    /**
     * @param world       the world's name
     * @param participant the robot's or environment's name
     * @param kind        {@code robot} or {@code environment}
     * @param panels      the module panels, in description order
     */
    public ParticipantWindow(String world, String participant, String kind, List<JComponent> panels) {
        super(title(world, participant, kind));
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        JPanel column = new JPanel();
        column.setLayout(new BoxLayout(column, BoxLayout.Y_AXIS));
        column.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        if (panels.isEmpty()) {
            column.add(new JLabel("This " + kind + " has no modules."));
        }
        for (JComponent panel : panels) {
            panel.setAlignmentX(LEFT_ALIGNMENT);
            column.add(panel);
            column.add(Box.createVerticalStrut(4));
        }
        getContentPane().add(new JScrollPane(column), BorderLayout.CENTER);
        pack();
    }

    /**
     * Shows a bar at the top of the window, outside the scrolled panels, so it is always visible: the STOP button
     * of the world.
     */
    public void showAtTop(JComponent bar) {
        getContentPane().add(bar, BorderLayout.NORTH);
        pack();
    }

    /** The window title for a participant. */
    public static String title(String world, String participant, String kind) {
        return "Monitor: " + participant + " (" + kind + ") - " + world;
    }
}
