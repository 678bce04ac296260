package robotworld.explorer.monitor.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.Timer;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.DefaultTableCellRenderer;
import robotworld.explorer.monitor.TrafficStatistics;
import robotworld.observe.Liveness;

/**
 * The status strip at the bottom of the monitor window: which participants are alive (a green dot while the
 * programs serving them send heartbeats, red when one has fallen silent or a request to them waits unserved, dark
 * grey once they ended, light grey while nothing tells) and, per module, its queue, calls per second, median
 * latency, errors and last answer; the dot's tooltip says what it rests on. Refreshed twice a second from
 * {@link TrafficStatistics}. Swing thread only.
 */
public final class StatusStrip extends JPanel {

    /** The dot of a participant whose programs run. */
    public static final Color ALIVE = new Color(0x2E, 0xA8, 0x5A);
    /** The dot of a participant with a silent program, or a request waiting unserved. */
    public static final Color NOT_ANSWERING = new Color(0xE0, 0x3A, 0x3E);
    /** The dot of a participant whose programs ended. */
    public static final Color ENDED = new Color(0x5C, 0x63, 0x6E);
    /** The dot of a quiet participant. */
    public static final Color UNKNOWN = new Color(0x9A, 0xA1, 0xAB);
    /** Rows shown without scrolling: a world's every module up to this many. */
    static final int VISIBLE_ROWS = 12;

    private final TrafficStatistics statistics;
    private final JPanel participants = new JPanel(new FlowLayout(FlowLayout.LEFT, 14, 2));
    private final Map<String, JLabel> dots = new LinkedHashMap<>();
    private final Rows rows = new Rows();
    private final JTable table = new JTable(rows);
    private final JLabel gaps = new JLabel();
    private final Timer refresh = new Timer(500, event -> refresh());

    public StatusStrip(TrafficStatistics statistics) {
        super(new BorderLayout(0, 2));
        this.statistics = statistics;
        setName("status strip");
        setBorder(BorderFactory.createEmptyBorder(2, 6, 4, 6));
        JPanel top = new JPanel(new BorderLayout());
        top.add(participants, BorderLayout.CENTER);
        gaps.setForeground(NOT_ANSWERING);
        top.add(gaps, BorderLayout.EAST);
        add(top, BorderLayout.NORTH);
        table.setFillsViewportHeight(true);
        table.setRowSelectionAllowed(false);
        table.setFocusable(false);
        table.getTableHeader().setReorderingAllowed(false);
        table.getAccessibleContext().setAccessibleName("modules");
        int[] widths = {120, 115, 58, 58, 88, 50, 290};
        for (int i = 0; i < widths.length; i++) {
            table.getColumnModel().getColumn(i).setPreferredWidth(widths[i]);
            if (i >= 2 && i <= 5) { // the figures keep their headers readable; names and answers give way
                int header = table.getTableHeader().getDefaultRenderer().getTableCellRendererComponent(table,
                        rows.getColumnName(i), false, false, -1, i).getPreferredSize().width + 6;
                table.getColumnModel().getColumn(i).setMinWidth(Math.max(widths[i], header));
                table.getColumnModel().getColumn(i).setPreferredWidth(Math.max(widths[i], header));
            }
        }
        // participant and module names whole (up to a limit); the last answer gives way
        java.awt.FontMetrics metrics = table.getFontMetrics(table.getFont());
        int[] names = {0, 0};
        for (TrafficStatistics.ModuleFigures f : statistics.snapshot().modules()) {
            names[0] = Math.max(names[0], metrics.stringWidth(f.module().participant()));
            names[1] = Math.max(names[1], metrics.stringWidth(f.module().name()));
        }
        for (int i = 0; i < 2; i++) {
            int width = Math.min(170, Math.max(widths[i], names[i] + 12));
            table.getColumnModel().getColumn(i).setMinWidth(Math.min(width, 100));
            table.getColumnModel().getColumn(i).setPreferredWidth(width);
        }
        table.getColumnModel().getColumn(6).setMinWidth(120);
        table.getColumnModel().getColumn(6).setPreferredWidth(200);
        DefaultTableCellRenderer numbers = new DefaultTableCellRenderer();
        numbers.setHorizontalAlignment(JLabel.RIGHT);
        for (int i = 2; i <= 5; i++) {
            table.getColumnModel().getColumn(i).setCellRenderer(numbers);
        }
        table.getColumnModel().getColumn(5).setCellRenderer(new DefaultTableCellRenderer() {
            @Override
            public Component getTableCellRendererComponent(JTable t, Object value, boolean selected, boolean focus,
                    int row, int column) {
                Component cell = super.getTableCellRendererComponent(t, value, selected, focus, row, column);
                setHorizontalAlignment(JLabel.RIGHT);
                cell.setForeground(value instanceof Long errors && errors > 0 ? NOT_ANSWERING : t.getForeground());
                return cell;
            }
        });
        JScrollPane scroll = new JScrollPane(table);
        int height = table.getTableHeader().getPreferredSize().height
                + table.getRowHeight() * Math.min(VISIBLE_ROWS, Math.max(1, statistics.snapshot().modules().size())) + 4;
        scroll.setPreferredSize(new Dimension(600, height));
        add(scroll, BorderLayout.CENTER);
        refresh();
    }

    @Override
    public void addNotify() {
        super.addNotify();
        refresh.start();
    }

    @Override
    public void removeNotify() {
        refresh.stop();
        super.removeNotify();
    }

    /** The dot and words of {@code participant}, or null. */
    public JLabel participantLabel(String participant) {
        return dots.get(participant);
    }

    /** The module table. */
    public JTable table() {
        return table;
    }

    /** Reads the statistics again (done by the timer; callable by tests). */
    public void refresh() {
        TrafficStatistics.Snapshot snapshot = statistics.snapshot();
        for (Liveness liveness : snapshot.participants()) {
            JLabel label = dots.computeIfAbsent(liveness.participant(), name -> {
                JLabel created = new JLabel();
                created.setFont(created.getFont().deriveFont(Font.BOLD));
                participants.add(created);
                participants.revalidate();
                return created;
            });
            label.setText("● " + liveness.participant() + ": " + words(liveness.state()));
            label.setForeground(colour(liveness.state()));
            label.setToolTipText(liveness.basis());
        }
        gaps.setText(snapshot.gaps() == 0 ? "" : "some events were missed (" + snapshot.gaps() + "×)");
        rows.show(snapshot.modules());
    }

    /** Words for a liveness state. */
    public static String words(Liveness.State state) {
        return switch (state) {
            case ALIVE -> "alive";
            case SILENT -> "SILENT";
            case ENDED -> "ended";
            case NOT_ANSWERING -> "NOT ANSWERING";
            case UNKNOWN -> "quiet";
        };
    }

    /** The dot's colour for a liveness state. */
    public static Color colour(Liveness.State state) {
        return switch (state) {
            case ALIVE -> ALIVE;
            case SILENT, NOT_ANSWERING -> NOT_ANSWERING;
            case ENDED -> ENDED;
            case UNKNOWN -> UNKNOWN;
        };
    }

    private static final class Rows extends AbstractTableModel {
        private static final String[] COLUMNS = {"Participant", "Module", "Queued", "Calls/s", "Latency p50",
            "Errors", "Last answer"};
        private List<TrafficStatistics.ModuleFigures> figures = new ArrayList<>();

        void show(List<TrafficStatistics.ModuleFigures> newFigures) {
            boolean sameRows = newFigures.size() == figures.size();
            figures = newFigures;
            if (sameRows) {
                fireTableRowsUpdated(0, Math.max(0, figures.size() - 1));
            } else {
                fireTableDataChanged();
            }
        }

        @Override
        public int getRowCount() {
            return figures.size();
        }

        @Override
        public int getColumnCount() {
            return COLUMNS.length;
        }

        @Override
        public String getColumnName(int column) {
            return COLUMNS[column];
        }

        @Override
        public Object getValueAt(int row, int column) {
            TrafficStatistics.ModuleFigures f = figures.get(row);
            return switch (column) {
                case 0 -> f.module().participant();
                case 1 -> f.module().name();
                case 2 -> f.queued();
                case 3 -> String.format(Locale.ROOT, "%.1f", f.callsPerSecond());
                case 4 -> f.medianLatency() == null ? "–"
                        : String.format(Locale.ROOT, "%.1f ms", f.medianLatency().toNanos() / 1e6);
                case 5 -> f.errors();
                default -> f.lastAnswer();
            };
        }
    }
}
