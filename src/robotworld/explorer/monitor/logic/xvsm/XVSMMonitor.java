package robotworld.explorer.monitor.logic.xvsm;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import javax.swing.SwingUtilities;
import robotworld.explorer.monitor.Monitor;
import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.gui.ModulePanel;
import robotworld.observe.AnswerSeen;
import robotworld.observe.Gap;
import robotworld.observe.ModuleRef;
import robotworld.observe.RequestSeen;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldObserver;
import robotworld.observe.WorldTap;
import robotworld.safety.StopRecord;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/**
 * What every XVSM monitor does (thesis table 3): watch the module's answers through a
 * {@link WorldTap} and, on the Swing thread, show what the ANSWER container already held (the module's last known
 * state), then mark the panel fresh on every answer, show error answers as problems (until the next call or good
 * answer) and hand good answers to {@link #show}. A subclass only says how an answer of its module type changes its panel.
 *
 * <p>Two ways to build one: with a {@link Capi} (the naming convention's constructor), it taps the module's
 * containers on its own; with a shared {@link WorldTap} (as the monitor window does for a whole world), it is one
 * more observer of that tap, which its owner starts. Create on the Swing thread: the first answer is shown only
 * after construction has finished.
 *
 * @param <P> the module's panel
 */
public abstract class XVSMMonitor<P extends ModulePanel> implements Monitor {

    private final MonitoredModule module;
    private final ModuleRef ref;
    private final P panel;
    private final WorldTap tap;
    private final boolean ownsTap;
    /** The key of the failed call whose problem the panel shows, or null. Swing thread. */
    private String problemKey;
    private final WorldObserver observer = new WorldObserver() {
        @Override
        public void answerSeen(AnswerSeen event) {
            if (event.module().equals(ref)) {
                SwingUtilities.invokeLater(() -> display(event.answer(), event.earlier() ? null : event.at()));
            }
        }

        @Override
        public void requestSeen(RequestSeen event) {
            if (event.module().equals(ref)) {
                String key = event.request().key();
                SwingUtilities.invokeLater(() -> newCall(key));
            }
        }

        @Override
        public void gap(Gap gap) {
            if (gap.module() != null && !gap.module().equals(ref)) {
                return;
            }
            if (gap.ended()) {
                SwingUtilities.invokeLater(() -> panel().showProblem("not watching: " + gap.why()));
            } else {
                // watching goes on, but answers may be missing (a slow monitor, or a cluster member that failed)
                SwingUtilities.invokeLater(() -> panel().showGap(gap.at(), gap.why()));
            }
        }
    };

    /** Watches {@code module} in {@code space} with a tap of its own, started in the background. */
    protected XVSMMonitor(MonitoredModule module, Capi space, P panel) {
        this(module, new WorldTap(space, new WorldLayout(module.participant(), List.of(new WorldLayout.Participant(
                module.participant(), "module", List.of(module.ref()))))), true, panel);
    }

    /** Watches {@code module} through {@code tap}, which its owner starts and closes. */
    protected XVSMMonitor(MonitoredModule module, WorldTap tap, P panel) {
        this(module, tap, false, panel);
    }

    private XVSMMonitor(MonitoredModule module, WorldTap tap, boolean ownsTap, P panel) {
        this.module = module;
        this.ref = module.ref();
        this.panel = panel;
        this.tap = tap;
        this.ownsTap = ownsTap;
        tap.add(observer);
        if (ownsTap) {
            tap.startInBackground();
        }
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

    private P panel() {
        return panel;
    }

    @Override
    public boolean awaitWatching(Duration timeout) throws InterruptedException {
        return tap.awaitWatching(timeout);
    }

    @Override
    public void close() {
        tap.remove(observer);
        if (ownsTap) {
            tap.close();
        }
    }

    /**
     * A new call to the module is on its way: a failed earlier call's problem line goes, so that what the panel
     * says belongs to the calls being made now. (The request of the very call that failed can be seen after its
     * error answer; it does not clear its own problem.)
     */
    private void newCall(String key) {
        if (problemKey != null && !problemKey.equals(key)) {
            clearProblem();
        }
    }

    private void clearProblem() {
        problemKey = null;
        panel.clearProblem();
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
            problemKey = answer.key();
            return;
        }
        try {
            show(answer, panel);
            clearProblem();
            if (when != null) {
                panel.clearStopped();
            }
        } catch (RuntimeException e) {
            panel.showProblem("unreadable answer " + answer + ": " + e.getMessage());
        }
    }
}
