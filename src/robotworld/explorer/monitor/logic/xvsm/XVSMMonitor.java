package robotworld.explorer.monitor.logic.xvsm;

import java.time.Duration;
import java.time.Instant;
import javax.swing.SwingUtilities;
import robotworld.explorer.monitor.Monitor;
import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.ModulePanel;
import robotworld.safety.StopRecord;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/**
 * What every XVSM monitor does (thesis table 3): watch the module's ANSWER container and, on the Swing thread,
 * show what it already held (the module's last known state), then mark the panel fresh on every answer, show
 * error answers as problems and hand good answers to {@link #show}. A subclass only says how an answer of its
 * module type changes its panel. Create on the Swing thread: the first answer is shown only after construction
 * has finished.
 *
 * @param <P> the module's panel
 */
public abstract class XVSMMonitor<P extends ModulePanel> implements Monitor {

    private final MonitoredModule module;
    private final P panel;
    private final AnswerWatcher watcher;

    /**
     * Starts watching the ANSWER container of {@code module} in {@code space}, in the background (the Swing thread
     * does not wait for the network); a failure is shown on the panel.
     */
    protected XVSMMonitor(MonitoredModule module, Capi space, P panel) {
        this.module = module;
        this.panel = panel;
        this.watcher = new AnswerWatcher(space, module.participant(), module.moduleName(), new AnswerListener() {
            @Override
            public void answer(CallTuple answer, Instant when) {
                SwingUtilities.invokeLater(() -> display(answer, when));
            }

            @Override
            public void earlier(CallTuple answer) {
                SwingUtilities.invokeLater(() -> display(answer, null));
            }

            @Override
            public void stopped(String why) {
                SwingUtilities.invokeLater(() -> panel.showProblem("not watching: " + why));
            }
        }).startInBackground();
    }

    /**
     * Shows a good answer of this module on the panel. Swing thread. May throw
     * {@link robotworld.xvsm.MalformedCallException} (or any runtime exception) for an answer it cannot read;
     * the panel then says so.
     */
    protected abstract void show(CallTuple answer, P panel);

    /**
     * Shows the module's safe state after a successful stop: the default shows nothing more than the stop line;
     * the motor monitor shows every motor at 0. Swing thread.
     */
    protected void showSafeState(StopRecord record, P panel) {
    }

    @Override
    public void stopped(StopRecord record) {
        SwingUtilities.invokeLater(() -> {
            panel.showStopped(record.summary().replaceFirst("^stopped ", ""));
            if (!record.action().startsWith("failed")) {
                showSafeState(record, panel);
            }
        });
    }

    /** The module watched. */
    public MonitoredModule module() {
        return module;
    }

    @Override
    public P getPanel() {
        return panel;
    }

    @Override
    public boolean awaitWatching(Duration timeout) throws InterruptedException {
        return watcher.awaitWatching(timeout);
    }

    @Override
    public void close() {
        watcher.close();
    }

    /** Shows an answer that arrived at {@code when}, or (null) one found when monitoring started. */
    private void display(CallTuple answer, Instant when) {
        if (when == null) {
            panel.reportedEarlier(AnswerText.host(answer));
        } else {
            panel.reported(when, AnswerText.host(answer));
        }
        if (AnswerText.isError(answer)) {
            panel.showProblem(AnswerText.function(answer) + ": " + AnswerText.errorMessage(answer));
            return;
        }
        try {
            show(answer, panel);
            panel.clearProblem();
            if (when != null) {
                panel.clearStopped();
            }
        } catch (RuntimeException e) {
            panel.showProblem("unreadable answer " + answer + ": " + e.getMessage());
        }
    }
}
