package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.Scrollable;
import javax.swing.ScrollPaneConstants;

/**
 * One participant's module panels, one below the other, as wide as the space they are given: they scroll up and
 * down, never sideways, so no field can end up out of view to the right.
 */
public final class ParticipantPanel extends JPanel {

    private final String participant;
    private final String kind;
    private final Column column = new Column();

    /**
     * @param participant the robot's or environment's name
     * @param kind        {@code robot} or {@code environment}
     * @param panels      the module panels, in description order
     */
    public ParticipantPanel(String participant, String kind, List<JComponent> panels) {
        super(new BorderLayout());
        this.participant = participant;
        this.kind = kind;
        setName(participant);
        column.setLayout(new BoxLayout(column, BoxLayout.Y_AXIS));
        column.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        if (panels.isEmpty()) {
            column.add(new JLabel("This " + kind + " has no modules."));
        }
        for (JComponent panel : panels) {
            panel.setAlignmentX(LEFT_ALIGNMENT);
            panel.setMaximumSize(new Dimension(Integer.MAX_VALUE, panel.getPreferredSize().height));
            column.add(panel);
            column.add(Box.createVerticalStrut(6));
        }
        JScrollPane scroll = new JScrollPane(column, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
        scroll.getVerticalScrollBar().setUnitIncrement(24);
        scroll.setBorder(null);
        add(scroll, BorderLayout.CENTER);
    }

    /** The participant shown. */
    public String participant() {
        return participant;
    }

    /** Whether it shows a robot. */
    public boolean isRobot() {
        return "robot".equals(kind);
    }

    /** The column of panels (the scroll pane's view). */
    public JComponent column() {
        return column;
    }

    /** A column that takes the viewport's width. */
    private static final class Column extends JPanel implements Scrollable {
        @Override
        public Dimension getPreferredScrollableViewportSize() {
            return getPreferredSize();
        }

        @Override
        public int getScrollableUnitIncrement(Rectangle visible, int orientation, int direction) {
            return 24;
        }

        @Override
        public int getScrollableBlockIncrement(Rectangle visible, int orientation, int direction) {
            return visible.height;
        }

        @Override
        public boolean getScrollableTracksViewportWidth() {
            return true;
        }

        @Override
        public boolean getScrollableTracksViewportHeight() {
            return false;
        }
    }
}
