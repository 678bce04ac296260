package robotworld.explorer.monitor.gui;

import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.GridLayout;
import java.awt.Rectangle;
import java.util.LinkedHashMap;
import java.util.Map;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JToggleButton;
import javax.swing.Scrollable;
import javax.swing.SwingConstants;
import javax.swing.Timer;
import org.jfree.chart.ChartPanel;
import org.jfree.chart.LegendItem;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.AbstractXYItemRenderer;
import org.jfree.chart.renderer.xy.SamplingXYLineRenderer;
import org.jfree.chart.renderer.xy.XYStepRenderer;
import org.jfree.chart.title.LegendTitle;
import org.jfree.chart.title.TextTitle;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.RectangleInsets;
import org.jfree.data.xy.DefaultXYDataset;
import robotworld.explorer.monitor.NumericChannels;
import robotworld.explorer.monitor.PlotModel;
import robotworld.explorer.monitor.TimeSeries;
import robotworld.observe.ModuleRef;

/**
 * Plots over time, drawn with JFreeChart: one chart per module with a line per channel (in the units of
 * {@link NumericChannels}), and one chart of every module's call latency. They show the last
 * {@value PlotModel#WINDOW_SECONDS} s of a {@link PlotModel} (whose memory is bounded), refreshed
 * {@value #REFRESHES_PER_SECOND} times a second while on screen; "Pause" freezes them (values keep being
 * collected). Swing thread only.
 */
public final class PlotsPanel extends JPanel {

    static final int REFRESHES_PER_SECOND = 2;
    /** A chart's height: two rows of charts fit below the world view at the window's default size. */
    static final int CHART_HEIGHT = 140;
    private static final int GAP = 6;
    private static final Color[] LINES = {new Color(0x1F, 0x77, 0xB4), new Color(0xFF, 0x7F, 0x0E),
        new Color(0x2C, 0xA0, 0x2C), new Color(0xD6, 0x27, 0x28), new Color(0x94, 0x67, 0xBD),
        new Color(0x8C, 0x56, 0x4B), new Color(0xE3, 0x77, 0xC2), new Color(0x7F, 0x7F, 0x7F)};
    private static final String LATENCY = "Call latency";

    private final PlotModel model;
    private final Map<String, Chart> charts = new LinkedHashMap<>();
    private final JToggleButton pause = new JToggleButton("Pause plots");
    private final JScrollPane scroll;
    private final JPanel header;
    private final Timer refresh = new Timer(1000 / REFRESHES_PER_SECOND, event -> refresh());

    /** One chart and what it shows. */
    private static final class Chart {
        final JFreeChart chart;
        final ChartPanel panel;
        final DefaultXYDataset data = new DefaultXYDataset();
        final PlotModel.ModuleSeries module;

        Chart(String title, String unit, PlotModel.ModuleSeries module, boolean steps) {
            this.module = module;
            NumberAxis time = new NumberAxis("s");
            NumberAxis values = new NumberAxis(unit);
            values.setAutoRangeIncludesZero(true);
            values.setAutoRangeMinimumSize(1); // a channel that stays at 0 gets an axis of 0..1, not of 1E-9s
            time.setAutoRange(false);
            // set-points and states hold until the next command: steps; measurements: lines
            AbstractXYItemRenderer renderer = steps ? new XYStepRenderer() : new SamplingXYLineRenderer();
            for (int i = 0; i < LINES.length; i++) {
                renderer.setSeriesPaint(i, LINES[i]);
                renderer.setSeriesStroke(i, new BasicStroke(2f));
            }
            XYPlot plot = new XYPlot(data, time, values, renderer);
            plot.setBackgroundPaint(Color.WHITE);
            plot.setDomainGridlinePaint(new Color(0xE4, 0xE7, 0xEB));
            plot.setRangeGridlinePaint(new Color(0xE4, 0xE7, 0xEB));
            plot.setNoDataMessage("no values yet");
            chart = new JFreeChart(null, JFreeChart.DEFAULT_TITLE_FONT, plot, true);
            chart.setTitle(new TextTitle(title, new Font(Font.SANS_SERIF, Font.BOLD, 12)));
            chart.setBackgroundPaint(Color.WHITE);
            chart.removeLegend();
            // a solid square per line, in its colour: a 2-pixel line sample is hard to tell apart at a glance
            LegendTitle legend = new LegendTitle(() -> {
                LegendItemCollection items = new LegendItemCollection();
                for (int i = 0; i < data.getSeriesCount(); i++) {
                    items.add(new LegendItem(String.valueOf(data.getSeriesKey(i)), null, null, null,
                            new Rectangle(-5, -5, 10, 10), LINES[i % LINES.length]));
                }
                return items;
            });
            legend.setPosition(RectangleEdge.RIGHT);
            legend.setItemFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
            legend.setBackgroundPaint(Color.WHITE);
            legend.setItemLabelPadding(new RectangleInsets(1, 3, 1, 2));
            chart.addLegend(legend);
            panel = new ChartPanel(chart, 360, CHART_HEIGHT, 200, 110, 2000, 1200, true, true, true, true, false,
                    false);
            panel.setDisplayToolTips(false);
            panel.setPreferredSize(new Dimension(360, CHART_HEIGHT));
            panel.getAccessibleContext().setAccessibleName("plot " + title);
        }
    }

    public PlotsPanel(PlotModel model) {
        this(model, java.util.Set.of());
    }

    /**
     * Plots with the charts of {@code first}'s modules (the robots: they move) before the others', each group in
     * the model's order.
     */
    public PlotsPanel(PlotModel model, java.util.Set<String> first) {
        super(new BorderLayout());
        this.model = model;
        setName("plots");
        pause.setMnemonic('U'); // Alt+P is the STOP button's, wherever there is one
        pause.setToolTipText("Freeze the plots; values are still collected");
        pause.addActionListener(event -> {
            pause.setText(pause.isSelected() ? "Resume plots" : "Pause plots");
            if (!pause.isSelected()) {
                refresh();
            }
        });
        JPanel header = new JPanel(new FlowLayout(FlowLayout.LEFT, 8, 2));
        header.add(pause);
        header.add(new JLabel("last " + (int) PlotModel.WINDOW_SECONDS + " s of every module's values and call latency"));
        add(header, BorderLayout.NORTH);
        Grid grid = new Grid();
        java.util.List<PlotModel.ModuleSeries> ordered = new java.util.ArrayList<>(model.modules());
        ordered.sort(java.util.Comparator.comparing(series -> !first.contains(series.module().participant())));
        for (PlotModel.ModuleSeries series : ordered) {
            ModuleRef module = series.module();
            boolean steps = !module.moduleClass().equals("IRDistanceModule");
            Chart chart = new Chart(module.label(), NumericChannels.unit(module.moduleClass()), series, steps);
            charts.put(module.label(), chart);
            grid.add(chart.panel);
        }
        Chart latency = new Chart(LATENCY, "ms", null, false);
        charts.put(LATENCY, latency);
        grid.add(latency.panel);
        if (model.modules().isEmpty()) {
            grid.add(new JLabel("This world has no modules.", SwingConstants.CENTER));
        }
        scroll = new JScrollPane(grid);
        scroll.getVerticalScrollBar().setUnitIncrement(24);
        add(scroll, BorderLayout.CENTER);
        this.header = header;
    }

    /** The height that shows {@code rows} rows of charts whole, with the pause button above them. */
    public int heightFor(int rows) {
        java.awt.Insets insets = scroll.getInsets();
        return header.getPreferredSize().height + rows * CHART_HEIGHT + Math.max(0, rows - 1) * GAP + insets.top
                + insets.bottom;
    }

    /** Charts in two columns, as wide as the scroll pane: they never scroll sideways. */
    private static final class Grid extends JPanel implements Scrollable {
        Grid() {
            super(new GridLayout(0, 2, GAP, GAP));
        }

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

    /** Whether the plots are frozen. */
    public boolean isPaused() {
        return pause.isSelected();
    }

    /** Freezes or resumes the plots. */
    public void setPaused(boolean paused) {
        if (paused != pause.isSelected()) {
            pause.doClick();
        }
    }

    /** The pause button. */
    public JToggleButton pauseButton() {
        return pause;
    }

    /** The chart of {@code module}. */
    public JFreeChart chartOf(ModuleRef module) {
        return charts.get(module.label()).chart;
    }

    /** The latency chart. */
    public JFreeChart latencyChart() {
        return charts.get(LATENCY).chart;
    }

    /** Scrolls the chart of {@code module} into view (charts out of view are not kept up to date). */
    public void reveal(ModuleRef module) {
        reveal(charts.get(module.label()));
    }

    /** Scrolls the latency chart into view. */
    public void revealLatency() {
        reveal(charts.get(LATENCY));
    }

    private static void reveal(Chart chart) {
        chart.panel.scrollRectToVisible(new Rectangle(0, 0, chart.panel.getWidth(), chart.panel.getHeight()));
    }

    /** How many charts are wholly in view now (not scrolled out, not cut by the panel's edge). */
    public int chartsInView() {
        int whole = 0;
        for (Chart chart : charts.values()) {
            java.awt.Rectangle visible = chart.panel.getVisibleRect();
            if (chart.panel.isShowing() && visible.width == chart.panel.getWidth()
                    && visible.height == chart.panel.getHeight()) {
                whole++;
            }
        }
        return whole;
    }

    /** Points the chart of {@code module} draws now, over all its lines. */
    public int pointsShown(ModuleRef module) {
        return points(charts.get(module.label()));
    }

    /** Points the latency chart draws now. */
    public int latencyPointsShown() {
        return points(charts.get(LATENCY));
    }

    private static int points(Chart chart) {
        int points = 0;
        for (int i = 0; i < chart.data.getSeriesCount(); i++) {
            points += chart.data.getItemCount(i);
        }
        return points;
    }

    /** Brings the visible charts up to date (done by the timer; callable by tests). */
    public void refresh() {
        if (isPaused()) {
            return;
        }
        double now = model.now();
        double from = Math.max(0, now - PlotModel.WINDOW_SECONDS);
        for (Map.Entry<String, Chart> entry : charts.entrySet()) {
            Chart chart = entry.getValue();
            if (!chart.panel.isShowing() || chart.panel.getVisibleRect().isEmpty()) {
                continue;
            }
            chart.chart.setNotify(false);
            try {
                ((XYPlot) chart.chart.getPlot()).getDomainAxis().setRange(from, Math.max(from + 1, now));
                if (entry.getKey().equals(LATENCY)) {
                    fillLatency(chart, from);
                } else {
                    fillChannels(chart, from);
                }
            } finally {
                chart.chart.setNotify(true);
            }
        }
    }

    private static void fillChannels(Chart chart, double from) {
        String type = chart.module.module().moduleClass();
        for (Map.Entry<Integer, TimeSeries> channel : chart.module.channels().entrySet()) {
            chart.data.addSeries(NumericChannels.channelName(type, channel.getKey()), channel.getValue().since(from));
        }
    }

    private void fillLatency(Chart chart, double from) {
        for (PlotModel.ModuleSeries series : model.modules()) {
            if (series.latency().size() > 0) {
                chart.data.addSeries(series.module().label(), series.latency().since(from));
            }
        }
    }
}
