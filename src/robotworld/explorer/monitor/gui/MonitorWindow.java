package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.WindowConstants;

/**
 * The one monitor window of a world: the world view (top left), the plots (below it), the status strip (bottom
 * left, as tall as its rows), and one tab per participant with its module panels (right, the window's whole
 * height, so that a robot's panels fit one below the other). Its size, maximized state, dividers and tab are
 * remembered between runs ({@link LayoutMemory}); the first time it takes a sensible share of the screen, with
 * the dividers at {@link #MAIN_SHARE} and {@link #VIEW_SHARE}.
 */
public final class MonitorWindow extends JFrame {

    /** The size the window opens at the first time (less on a smaller screen). */
    public static final Dimension DEFAULT_SIZE = new Dimension(1360, 900);
    /** The first time: the share of the width for the world view, plots and status strip (the tabs get the rest). */
    public static final double MAIN_SHARE = 0.58;
    /**
     * The first time: the world view's least share of the height above the status strip; the plots get the rest,
     * up to {@link #PLOT_ROWS} rows of charts.
     */
    public static final double VIEW_SHARE = 0.5;
    /** The first time: rows of charts shown whole below the world view, where the height allows. */
    public static final int PLOT_ROWS = 2;

    private final String world;
    private final WorldView view;
    private final PlotsPanel plots;
    private final StatusStrip strip;
    private final JTabbedPane tabs = new JTabbedPane();
    private final List<ParticipantPanel> participants;
    private final JSplitPane left;
    private final JSplitPane main;
    private final LayoutMemory memory;
    private boolean saved;
    private boolean defaultViewDivider;

    public MonitorWindow(String world, List<ParticipantPanel> participants, WorldView view, PlotsPanel plots,
            StatusStrip strip, LayoutMemory memory) {
        super(title(world));
        this.world = world;
        this.view = view;
        this.plots = plots;
        this.strip = strip;
        this.participants = new ArrayList<>(participants);
        this.memory = memory;
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        for (ParticipantPanel participant : participants) {
            tabs.addTab(participant.participant(), participant);
        }
        tabs.getAccessibleContext().setAccessibleName("participants");
        left = new JSplitPane(JSplitPane.VERTICAL_SPLIT, true, view, plots) {
            @Override
            public void doLayout() {
                // the first time on screen (its height known, with the window's decorations): two rows of charts
                // whole, the rest (at least VIEW_SHARE) for the world view
                if (defaultViewDivider && isDisplayable() && getHeight() > 0) {
                    defaultViewDivider = false;
                    int height = getHeight() - getDividerSize();
                    setDividerLocation(Math.max((int) (height * VIEW_SHARE), height - plots.heightFor(PLOT_ROWS)));
                }
                super.doLayout();
            }
        };
        left.setResizeWeight(VIEW_SHARE);
        left.setOneTouchExpandable(true);
        JPanel leftColumn = new JPanel(new BorderLayout());
        leftColumn.add(left, BorderLayout.CENTER);
        leftColumn.add(strip, BorderLayout.SOUTH); // as tall as its rows: every module's figures in view
        main = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, true, leftColumn, tabs);
        main.setResizeWeight(MAIN_SHARE);
        main.setOneTouchExpandable(true);
        getContentPane().add(main, BorderLayout.CENTER);
        applyLayout();
    }

    /** The window title of a world's monitor. */
    public static String title(String world) {
        return "Monitor: " + world + " - RobotWorldExplorer";
    }

    private void applyLayout() {
        Rectangle screen = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        Rectangle remembered = memory.bounds();
        if (remembered != null && screen.intersects(remembered)) {
            setBounds(remembered);
        } else {
            int width = Math.min(DEFAULT_SIZE.width, (int) (screen.width * 0.92));
            int height = Math.min(DEFAULT_SIZE.height, (int) (screen.height * 0.92));
            setBounds(screen.x + (screen.width - width) / 2, screen.y + (screen.height - height) / 2, width, height);
        }
        if (memory.flag("window.maximized") && Toolkit.getDefaultToolkit().isFrameStateSupported(MAXIMIZED_BOTH)) {
            setExtendedState(MAXIMIZED_BOTH);
        }
        int mainDivider = memory.number("divider.main", -1);
        int leftDivider = memory.number("divider.left", -1);
        main.setDividerLocation(mainDivider > 50 && mainDivider < getWidth() - 50 ? mainDivider
                : (int) (getWidth() * MAIN_SHARE));
        if (leftDivider > 50 && leftDivider < getHeight() - 100) {
            left.setDividerLocation(leftDivider);
        } else {
            defaultViewDivider = true; // placed at the first layout on screen
        }
        String tab = memory.text("tab." + world, null);
        for (int i = 0; tab == null && i < this.participants.size(); i++) {
            if (this.participants.get(i).isRobot()) {
                tab = this.participants.get(i).participant(); // robots first: they move
            }
        }
        for (int i = 0; i < tabs.getTabCount(); i++) {
            if (tabs.getTitleAt(i).equals(tab)) {
                tabs.setSelectedIndex(i);
            }
        }
    }

    /** Shows a bar at the top of the window, always visible: the world's STOP button. */
    public void showAtTop(javax.swing.JComponent bar) {
        getContentPane().add(bar, BorderLayout.NORTH);
        validate();
    }

    /** Remembers the layout, then closes. */
    @Override
    public void dispose() {
        if (!saved && isDisplayable()) {
            saved = true;
            boolean maximized = (getExtendedState() & MAXIMIZED_BOTH) == MAXIMIZED_BOTH;
            if (!maximized) {
                memory.bounds(getBounds());
            }
            memory.put("window.maximized", maximized).put("divider.main", main.getDividerLocation())
                    .put("divider.left", left.getDividerLocation());
            if (tabs.getSelectedIndex() >= 0) {
                memory.put("tab." + world, tabs.getTitleAt(tabs.getSelectedIndex()));
            }
            memory.save();
        }
        super.dispose();
    }

    /** The world view. */
    public WorldView worldView() {
        return view;
    }

    /** The plots. */
    public PlotsPanel plots() {
        return plots;
    }

    /** The status strip. */
    public StatusStrip statusStrip() {
        return strip;
    }

    /** The participants' tabs. */
    public JTabbedPane tabs() {
        return tabs;
    }

    /** The tab content of each participant, in order. */
    public List<ParticipantPanel> participants() {
        return List.copyOf(participants);
    }

    /** The divider between the left side and the tabs. */
    public JSplitPane mainSplit() {
        return main;
    }

    /** The divider between world view and plots. */
    public JSplitPane leftSplit() {
        return left;
    }
}
