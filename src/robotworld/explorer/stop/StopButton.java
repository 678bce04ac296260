package robotworld.explorer.stop;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Font;
import java.util.Objects;
import java.util.concurrent.ExecutionException;
import java.util.function.Supplier;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingWorker;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.safety.WorldStop;
import robotworld.space.Capi;

/**
 * The STOP button every window that watches or launches a world shows: one click stops every actuator of the
 * world through its space ({@link WorldStopper}), off the Swing thread, and the line beside it says what came of
 * it (green: every actuator confirmed stopped; red: which were not, with every module's outcome in the tooltip).
 * Swing thread only.
 */
public final class StopButton extends JPanel {

    /** The text of the button. */
    public static final String TEXT = "STOP";

    private static final Color RED = new Color(0xC0, 0x10, 0x10);
    private static final Color GOOD = new Color(0x00, 0x70, 0x20);
    private static final Color BAD = new Color(0xB0, 0x00, 0x20);

    /**
     * What to stop.
     *
     * @param world    the world
     * @param spaceUrl its space
     * @param space    an open connection to it, or null to open one for the stop
     */
    public record Scope(MonitoredWorld world, String spaceUrl, Capi space) {

        /** Checks the world. */
        public Scope {
            Objects.requireNonNull(world, "world");
        }
    }

    private final JButton button = new JButton(TEXT);
    private final JLabel outcome = new JLabel(" ");
    private final String via;
    private final Supplier<Scope> scope;
    private volatile WorldStop.Result lastResult;
    private volatile String lastProblem;

    /**
     * @param via   how the stop reads in the records, e.g. {@code STOP button of the launcher}
     * @param scope what to stop when clicked; null when it is not known (the supplier tells the user what is
     *              missing itself, e.g. by asking for a world, and returns null if the user gives none)
     */
    public StopButton(String via, Supplier<Scope> scope) {
        super(new BorderLayout(8, 0));
        this.via = Objects.requireNonNull(via, "via");
        this.scope = Objects.requireNonNull(scope, "scope");
        button.setName("stop");
        button.setMnemonic('P'); // Alt+P everywhere: Alt+S is taken by "Space URL" in the monitor frame
        button.setBackground(RED);
        button.setForeground(Color.WHITE);
        button.setOpaque(true);
        button.setFont(button.getFont().deriveFont(Font.BOLD, button.getFont().getSize2D() * 1.4f));
        button.setToolTipText("Stop every actuator of the world now: motors 0, servos hold (see docs/safety.md)");
        button.getAccessibleContext().setAccessibleName("Stop every actuator of the world");
        button.addActionListener(event -> stopNow());
        outcome.setName("stop outcome");
        setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        add(button, BorderLayout.WEST);
        add(outcome, BorderLayout.CENTER);
    }

    /** The button. */
    public JButton button() {
        return button;
    }

    /** The line that says what the last stop did. */
    public String outcomeText() {
        return outcome.getText();
    }

    /** The result of the last stop, or null. */
    public WorldStop.Result lastResult() {
        return lastResult;
    }

    /** Why the last stop could not be sent, or null. */
    public String lastProblem() {
        return lastProblem;
    }

    /** Sends the stop now (what a click does). */
    public void stopNow() {
        Scope target = scope.get();
        if (target == null) {
            return;
        }
        button.setEnabled(false);
        outcome.setForeground(null);
        outcome.setText("stopping every actuator of " + target.world().name() + "...");
        new SwingWorker<WorldStop.Result, Void>() {
            @Override
            protected WorldStop.Result doInBackground() throws Exception {
                if (target.space() != null) {
                    return WorldStopper.stop(target.world(), target.space(), via, "", WorldStop.DEFAULT_WAIT);
                }
                return WorldStopper.stop(target.world(), target.spaceUrl(), via, "", WorldStop.DEFAULT_WAIT);
            }

            @Override
            protected void done() {
                button.setEnabled(true);
                try {
                    show(get());
                } catch (ExecutionException e) {
                    Throwable cause = e.getCause();
                    lastProblem = cause.getMessage() == null ? cause.toString() : cause.getMessage();
                    outcome.setForeground(BAD);
                    outcome.setText("NOT stopped: " + lastProblem);
                    outcome.setToolTipText(lastProblem);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
    }

    private void show(WorldStop.Result result) {
        lastResult = result;
        lastProblem = null;
        outcome.setForeground(result.complete() ? GOOD : BAD);
        outcome.setText(WorldStopper.shortSummary(result));
        StringBuilder lines = new StringBuilder("<html>").append(escape(WorldStopper.summary(result))).append("<br>");
        for (WorldStop.Outcome each : result.outcomes()) {
            lines.append(escape(each.toString())).append("<br>");
        }
        outcome.setToolTipText(lines.append("</html>").toString());
    }

    private static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
