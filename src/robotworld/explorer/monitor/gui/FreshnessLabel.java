package robotworld.explorer.monitor.gui;

import java.time.Duration;
import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import javax.swing.JLabel;
import javax.swing.Timer;

/**
 * Says when a module last reported and from which host, with the age ("3 s ago") kept current by a timer that
 * runs only while the label is on screen. Swing thread only.
 */
public final class FreshnessLabel extends JLabel {

    /** Text before the first report. */
    public static final String NO_REPORT = "no report yet";

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss");
    private static final int REFRESH_MILLIS = 1_000;

    private final Timer refresh = new Timer(REFRESH_MILLIS, event -> render());
    private Instant lastReport;
    private String host;
    /** A report found when monitoring started, and none since. */
    private boolean earlier;

    public FreshnessLabel() {
        super(NO_REPORT);
        getAccessibleContext().setAccessibleName("last report");
    }

    /** The module reported at {@code when}, answering {@code byHost}. */
    public void reported(Instant when, String byHost) {
        this.lastReport = when;
        this.host = byHost;
        render();
    }

    /** The module reported before monitoring started (when is unknown), answering {@code byHost}. */
    public void reportedEarlier(String byHost) {
        if (lastReport == null) {
            this.earlier = true;
            this.host = byHost;
            render();
        }
    }

    /** As wide as its place, never wider: the text changes every second, the layout must not. */
    @Override
    public java.awt.Dimension getPreferredSize() {
        return new java.awt.Dimension(40, super.getPreferredSize().height);
    }

    /** When the module last reported, or null. */
    public Instant lastReport() {
        return lastReport;
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

    private void render() {
        if (lastReport == null) {
            setText(earlier ? "reported before monitoring started" + (host == null ? "" : " for " + host)
                    : NO_REPORT);
            return;
        }
        long seconds = Math.max(0, Duration.between(lastReport, Instant.now()).toSeconds());
        setText("last report " + TIME.format(LocalTime.ofInstant(lastReport, ZoneId.systemDefault()))
                + (host == null ? "" : " for " + host) + ", " + age(seconds));
    }

    private static String age(long seconds) {
        if (seconds < 60) {
            return seconds + " s ago";
        }
        return seconds < 3600 ? seconds / 60 + " min ago" : seconds / 3600 + " h ago";
    }
}
