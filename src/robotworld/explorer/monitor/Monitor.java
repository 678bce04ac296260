package robotworld.explorer.monitor;

import java.time.Duration;
import javax.swing.JComponent;

/**
 * Watches one module of a running RobotWorld and shows what it does (thesis 4.2.4). An implementation for
 * communication type {@code <type>} and module class {@code <Class>} is named
 * {@code robotworld.explorer.monitor.logic.<type>.<TYPE><Class>Monitor} and has a public constructor
 * {@code (MonitoredModule, Capi)}; {@link MonitorLoader} finds it by that name, so adding a module type needs
 * no change here. Create monitors on the Swing event thread; they update their panel on it.
 */
public interface Monitor extends AutoCloseable {

    /** The panel showing the module's state; the same component on every call. */
    JComponent getPanel();

    /**
     * Waits until the monitor watches its module: a monitor may start watching in the background, so that the
     * Swing thread never waits for the network. Not on the Swing thread. Default: already watching.
     *
     * @return whether it watches (false: its start failed, which its panel shows, or took longer than
     *         {@code timeout})
     */
    default boolean awaitWatching(Duration timeout) throws InterruptedException {
        return true;
    }

    /**
     * The module was put into its safe state (see {@code robotworld.safety}): the panel says who stopped it, when
     * and why, until the module is commanded again. Called on any thread. Default: nothing.
     */
    default void stopped(robotworld.safety.StopRecord record) {
    }

    /** Stops watching (cancels subscriptions); idempotent. The panel stays as it was. */
    @Override
    void close();
}
